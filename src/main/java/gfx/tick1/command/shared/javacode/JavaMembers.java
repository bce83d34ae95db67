package gfx.tick1.command.shared.javacode;

import com.github.javaparser.JavaParser;
import com.github.javaparser.ParseResult;
import com.github.javaparser.ParserConfiguration;
import com.github.javaparser.Position;
import com.github.javaparser.Problem;
import com.github.javaparser.ast.CompilationUnit;
import com.github.javaparser.ast.Node;
import com.github.javaparser.ast.body.BodyDeclaration;
import com.github.javaparser.ast.body.CallableDeclaration;
import com.github.javaparser.ast.body.FieldDeclaration;
import com.github.javaparser.ast.body.TypeDeclaration;
import com.github.javaparser.ast.body.VariableDeclarator;
import com.github.javaparser.ast.expr.ArrayAccessExpr;
import com.github.javaparser.ast.expr.EnclosedExpr;
import com.github.javaparser.ast.expr.Expression;
import com.github.javaparser.ast.expr.FieldAccessExpr;
import com.github.javaparser.ast.expr.LiteralExpr;
import com.github.javaparser.ast.expr.MethodCallExpr;
import com.github.javaparser.ast.expr.NameExpr;
import com.github.javaparser.ast.expr.ObjectCreationExpr;
import com.github.javaparser.ast.expr.ThisExpr;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.function.Predicate;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

/**
 * One Java file as {@code tick1 diff} compares it: the name of its class and its members, each
 * printed in one standard layout, keyed by signature. Comments, formatting, the package and
 * imports are set aside, and so are parentheses that change nothing ({@code (O.subtract(C)).dot}
 * is {@code O.subtract(C).dot}) and a {@code this.} before a method call.
 *
 * @param className the name of the file's first class
 * @param members   member signature ("intersectionWith(Ray)", "field radius") to its printed text, in
 *                  the file's order
 * @param tooDeep   the members not compared, nested too deeply ({@link Nesting}), in the file's order
 */
public record JavaMembers(String className, Map<String, Member> members, List<TooDeep> tooDeep) {

    /** Where the lexer's message says it stopped: "Lexical error at line 2, column 19.  Encountered: ...". */
    private static final Pattern LEXER_PLACE = Pattern.compile(" at line (\\d+), column (\\d+)");

    /**
     * One member: its text in the standard layout (with its independent declarations in
     * canonical order), its canonical text ({@link SameMeaning}: equal exactly when two members
     * mean the same), and whether the source marks it as still to be written with a TODO comment.
     */
    public record Member(String text, String key, boolean todo) {

        /** The text's lines and the key's, line for line (one statement a line in both). */
        public List<String> lines() {
            return text.lines().toList();
        }

        public List<String> keyLines() {
            List<String> keys = key.lines().toList();
            return keys.size() == lines().size() ? keys : lines();
        }
    }

    /**
     * A member not compared, nested too deeply ({@link Nesting}), and where.
     *
     * @param file      the file's name, as given to {@link #parse(String, String)}
     * @param signature the member's signature, "deep()"
     * @param line      with {@code column}, where: the start of a node deeper than {@link Nesting#MOST_DEPTH}, or
     *                  of the member whose nesting takes the file's past {@link Nesting#MOST_TOTAL}
     * @param inAll     whether the member is nested too deeply only with the file's members before it
     */
    public record TooDeep(String file, String signature, int line, int column, boolean inAll) {

        /** Why it is not compared: "blocks, statements and expressions nested more than 300 deep". */
        public String why() {
            return inAll ? "the depths of the file's blocks, statements and expressions, added up, pass "
                    + Nesting.MOST_TOTAL : "blocks, statements and expressions nested more than " + Nesting.MOST_DEPTH
                    + " deep";
        }

        /** "Sphere.java:3:317: deep(): blocks, statements and expressions nested more than 300 deep: too ...". */
        public String message() {
            return file + ":" + line + ":" + column + ": " + signature + ": " + why() + ": too deeply nested to "
                    + "compare";
        }
    }

    public JavaMembers {
        tooDeep = List.copyOf(tooDeep);
    }

    /** A file's members, all of them compared. */
    public JavaMembers(String className, Map<String, Member> members) {
        this(className, members, List.of());
    }

    /** A file that is not Java the parser accepts: where, and what the parser said. */
    public static final class ParseException extends Exception {
        private static final long serialVersionUID = 1L;

        ParseException(String message) {
            super(message);
        }
    }

    /** Parses {@code source}; {@code name} is the file's name for messages ("Sphere.java:12:5: ..."). */
    public static JavaMembers parse(String name, String source) throws ParseException {
        return parse(name, source, className -> null);
    }

    /**
     * Parses {@code source} as {@link #parse(String, String)} does, putting independent
     * declarations that {@code like} (ours; null for none) has in the order they have there.
     */
    public static JavaMembers parse(String name, String source, JavaMembers like) throws ParseException {
        return parse(name, source, className -> like);
    }

    /**
     * As {@link #parse(String, String, JavaMembers)}, keeping only the members whose signature
     * {@code wanted} accepts (the others are neither ordered nor printed, which is most of the cost).
     */
    public static JavaMembers parse(String name, String source, JavaMembers like, Predicate<String> wanted)
            throws ParseException {
        return parse(name, source, className -> like, wanted);
    }

    /** As {@link #parse(String, String, JavaMembers)}, with the members to be like found by the class's name. */
    public static JavaMembers parse(String name, String source, Function<String, JavaMembers> likeOf)
            throws ParseException {
        return parse(name, source, likeOf, signature -> true);
    }

    private static JavaMembers parse(String name, String source, Function<String, JavaMembers> likeOf,
            Predicate<String> wanted) throws ParseException {
        // A tab is one column, as it is one step of an editor's cursor (and one character of a scene's errors).
        JavaParser parser = new JavaParser(new ParserConfiguration()
                .setLanguageLevel(ParserConfiguration.LanguageLevel.JAVA_17).setTabSize(1));
        ParseResult<CompilationUnit> result = parser.parse(source);
        if (!result.isSuccessful() || result.getResult().isEmpty()) {
            Problem problem = result.getProblems().get(0);
            throw new ParseException(name + where(problem) + ": "
                    + firstLine(problem.getMessage()).replaceFirst(LEXER_PLACE.pattern() + "\\.?", "."));
        }
        CompilationUnit unit = result.getResult().get();
        if (unit.getTypes().isEmpty()) {
            throw new ParseException(name + ": no class in the file");
        }
        TypeDeclaration<?> type = unit.getType(0);
        dropParenthesesThatChangeNothing(type);
        dropThisBeforeMethodCalls(type);
        SameMeaning meaning = new SameMeaning(type);
        JavaMembers like = likeOf.apply(type.getNameAsString());
        Map<String, Member> members = new LinkedHashMap<>();
        List<TooDeep> tooDeep = new ArrayList<>();
        long total = 0;
        for (BodyDeclaration<?> member : type.getMembers()) {
            String signature = signature(member);
            if (!wanted.test(signature)) {
                continue;
            }
            Nesting nesting = Nesting.of(member);
            total += nesting.total();
            if (nesting.deepest() != null || total > Nesting.MOST_TOTAL) {
                Node at = nesting.deepest() != null ? nesting.deepest() : member;
                Position place = at.getBegin().orElse(Position.HOME);
                tooDeep.add(new TooDeep(name, signature, place.line, place.column, nesting.deepest() == null));
                total -= nesting.total();
                continue;
            }
            boolean todo = member.getAllContainedComments().stream()
                    .anyMatch(comment -> comment.getContent().contains("TODO"));
            Member ours = like == null ? null : like.members().get(signature);
            List<String> preferred = ours == null ? List.of() : ours.key().lines().map(String::strip).toList();
            meaning.order(member, preferred);
            members.put(signature, new Member(SameMeaning.print(member), meaning.key(member, preferred), todo));
        }
        return new JavaMembers(type.getNameAsString(), members, tooDeep);
    }

    /** "trace(Scene, Ray)", "Renderer(int, int)", "field width, height". */
    static String signature(BodyDeclaration<?> member) {
        if (member instanceof CallableDeclaration<?> callable) {
            return callable.getNameAsString() + "(" + callable.getParameters().stream()
                    .map(parameter -> parameter.getType().asString() + (parameter.isVarArgs() ? "..." : ""))
                    .collect(Collectors.joining(", ")) + ")";
        }
        if (member instanceof FieldDeclaration field) {
            return "field " + field.getVariables().stream().map(VariableDeclarator::getNameAsString)
                    .collect(Collectors.joining(", "));
        }
        if (member instanceof TypeDeclaration<?> nested) {
            return "class " + nested.getNameAsString();
        }
        return member.getClass().getSimpleName() + " at line " + member.getBegin().map(p -> p.line).orElse(0);
    }

    /** (x) where x is a name, a call, a field, a literal or a new object, or a whole initialiser or statement. */
    private static void dropParenthesesThatChangeNothing(Node root) {
        List<EnclosedExpr> enclosed = root.findAll(EnclosedExpr.class);
        for (EnclosedExpr parentheses : enclosed) {
            Expression inner = parentheses.getInner();
            boolean primary = inner instanceof NameExpr || inner instanceof MethodCallExpr
                    || inner instanceof FieldAccessExpr || inner instanceof LiteralExpr
                    || inner instanceof ObjectCreationExpr || inner instanceof ArrayAccessExpr
                    || inner instanceof ThisExpr || inner instanceof EnclosedExpr;
            boolean whole = parentheses.getParentNode().map(parent -> !(parent instanceof Expression)
                    || parent instanceof MethodCallExpr call && call.getArguments().contains(parentheses))
                    .orElse(false);
            if (primary || whole) {
                parentheses.replace(inner);
            }
        }
    }

    private static void dropThisBeforeMethodCalls(Node root) {
        for (MethodCallExpr call : root.findAll(MethodCallExpr.class)) {
            if (call.getScope()
                    .filter(scope -> scope instanceof ThisExpr plainThis && plainThis.getTypeName().isEmpty())
                    .isPresent()) {
                call.removeScope();
            }
        }
    }

    /**
     * ":line:column" of what the parser could not take, 1-based: the token it found (the problem's range begins at
     * the token before it, which is not where the student must look), or the place a lexer's error names; else
     * the start of the problem's range, or nothing.
     */
    private static String where(Problem problem) {
        if (problem.getCause().orElse(null) instanceof com.github.javaparser.ParseException e
                && e.currentToken != null && e.currentToken.next != null) {
            return ":" + e.currentToken.next.beginLine + ":" + Math.max(1, e.currentToken.next.beginColumn);
        }
        Matcher lexer = LEXER_PLACE.matcher(problem.getMessage());
        if (lexer.find()) {
            return ":" + lexer.group(1) + ":" + Math.max(1, Integer.parseInt(lexer.group(2)));
        }
        return problem.getLocation().flatMap(range -> range.getBegin().getRange())
                .map(range -> ":" + range.begin.line + ":" + range.begin.column).orElse("");
    }

    private static String firstLine(String message) {
        int end = message.indexOf('\n');
        return (end < 0 ? message : message.substring(0, end)).strip();
    }
}
