package gfx.tick1.cli;

import picocli.CommandLine.Help;
import picocli.CommandLine.Help.Ansi.Text;
import picocli.CommandLine.Model.CommandSpec;

/**
 * Picocli's help, with usage lines broken only between the tokens of the synopsis. Picocli
 * wraps with Java's line BreakIterator, which allows a break after any full stop followed by a
 * letter, and so splits {@code [-i=SCENE.xml]} into {@code [-i=SCENE.} and {@code xml]}; a token
 * of the synopsis is one thing to type, and stays on one line.
 */
public final class WholeTokenHelp extends Help {

    public WholeTokenHelp(CommandSpec spec, ColorScheme colorScheme) {
        super(spec, colorScheme);
    }

    /** Lays out "Usage: NAME" and the synopsis's tokens, continued lines indented past the name. */
    @Override
    protected String insertSynopsisCommandName(int headingLength, Text details) {
        String name = commandSpec().qualifiedName();
        int indent = headingLength + name.length() + 1;
        int width = Math.max(commandSpec().usageMessage().width(), indent + 20);
        String plain = details.plainString();
        StringBuilder lines = new StringBuilder(colorScheme().commandText(name).toString());
        int column = headingLength + name.length();
        int start = 0;
        while (start < plain.length()) {
            if (plain.charAt(start) == ' ') {
                start++;
                continue;
            }
            int end = plain.indexOf(' ', start);
            end = end < 0 ? plain.length() : end;
            int length = end - start;
            if (column + 1 + length > width && column > indent) {
                lines.append(System.lineSeparator()).append(" ".repeat(indent - 1));
                column = indent - 1;
            }
            lines.append(' ').append(details.substring(start, end).toString());
            column += 1 + length;
            start = end;
        }
        return lines.append(System.lineSeparator()).toString();
    }
}
