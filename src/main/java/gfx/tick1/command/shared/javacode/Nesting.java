package gfx.tick1.command.shared.javacode;

import com.github.javaparser.ast.Node;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Iterator;

/**
 * How deeply a member's code is nested: how far below the member's declaration its deepest node lies, and the depths
 * of all its nodes added up, each counting every block, statement and expression it is in. Printing indents each
 * block and statement by its depth, so the text of a member grows with the sum, and a member nested thousands deep
 * would print to more than a Java's heap holds: code nested beyond the bounds here is not compared.
 *
 * @param deepest a node that lies more than {@link #MOST_DEPTH} below the member, or null when none does
 * @param total   the depths of the member's nodes added up (those walked: none below {@code deepest})
 */
public record Nesting(Node deepest, long total) {

    /**
     * The deepest a node of a member may lie for the member to be compared. A solution's deepest node lies tens of
     * nodes down (an expression of a few calls, in an if, in a loop, in a method): ten times that leaves room for
     * every honest style.
     */
    public static final int MOST_DEPTH = 300;
    /**
     * The most that the totals of a file's members compared may add up to: a solution's come to a few thousand, and
     * a few dozen times that keeps the text printed for a file small, whatever the file holds.
     */
    public static final long MOST_TOTAL = 100_000;

    /** The nesting of {@code member}, walked with a stack of its own, not the thread's, however deep it goes. */
    static Nesting of(Node member) {
        Deque<Iterator<Node>> path = new ArrayDeque<>();
        path.push(member.getChildNodes().iterator());
        long total = 0;
        while (!path.isEmpty()) {
            Iterator<Node> children = path.peek();
            if (!children.hasNext()) {
                path.pop();
                continue;
            }
            Node child = children.next();
            if (path.size() > MOST_DEPTH) {
                return new Nesting(child, total);
            }
            total += path.size();
            path.push(child.getChildNodes().iterator());
        }
        return new Nesting(null, total);
    }
}
