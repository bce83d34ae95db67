package gfx.tick1.command.shared.javacode;

import com.github.javaparser.ast.Node;
import com.github.javaparser.ast.NodeList;
import com.github.javaparser.ast.body.BodyDeclaration;
import com.github.javaparser.ast.body.FieldDeclaration;
import com.github.javaparser.ast.body.Parameter;
import com.github.javaparser.ast.body.TypeDeclaration;
import com.github.javaparser.ast.body.VariableDeclarator;
import com.github.javaparser.ast.expr.AssignExpr;
import com.github.javaparser.ast.expr.BinaryExpr;
import com.github.javaparser.ast.expr.CastExpr;
import com.github.javaparser.ast.expr.ConditionalExpr;
import com.github.javaparser.ast.expr.EnclosedExpr;
import com.github.javaparser.ast.expr.Expression;
import com.github.javaparser.ast.expr.FieldAccessExpr;
import com.github.javaparser.ast.expr.InstanceOfExpr;
import com.github.javaparser.ast.expr.LambdaExpr;
import com.github.javaparser.ast.expr.NameExpr;
import com.github.javaparser.ast.expr.ObjectCreationExpr;
import com.github.javaparser.ast.expr.SwitchExpr;
import com.github.javaparser.ast.expr.ThisExpr;
import com.github.javaparser.ast.expr.UnaryExpr;
import com.github.javaparser.ast.expr.VariableDeclarationExpr;
import com.github.javaparser.ast.stmt.BlockStmt;
import com.github.javaparser.ast.stmt.Statement;
import com.github.javaparser.printer.DefaultPrettyPrinter;
import com.github.javaparser.printer.configuration.DefaultConfigurationOption;
import com.github.javaparser.printer.configuration.DefaultPrinterConfiguration;
import com.github.javaparser.printer.configuration.DefaultPrinterConfiguration.ConfigOption;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;

/**
 * The canonical text of a member, equal for two members exactly when they are the same program
 * up to what cannot change its meaning:
 * <ul>
 * <li>parentheses: all are dropped, then every operator expression inside another expression is
 *     put in parentheses, so the text shows the tree the parser built and nothing else
 *     ({@code (a + b) * c} and {@code a + b * c} stay apart, {@code (O.subtract(C)).dot(D)} and
 *     {@code O.subtract(C).dot(D)} meet);</li>
 * <li>consistent renaming of locals and parameters, and the order of independent declarations
 *     ({@link LocalNames});</li>
 * <li>{@code this.} on a field of the class, which, once every local has a name no field can
 *     have, no local shadows; where the member's locals are not followed, only on a field no
 *     declaration of the member is named like;</li>
 * <li>{@code final} and annotations on a local or a parameter, which only forbid assignments or
 *     inform tools: the program that compiles computes the same with them or without;</li>
 * <li>{@code this.} before a method call, comments and layout (as {@link JavaMembers} reads them).</li>
 * </ul>
 * Anything else, however equivalent in arithmetic, is a difference.
 */
public final class SameMeaning {

    private static final DefaultPrettyPrinter PRINTER = new DefaultPrettyPrinter(new DefaultPrinterConfiguration()
            .removeOption(new DefaultConfigurationOption(ConfigOption.PRINT_COMMENTS))
            .removeOption(new DefaultConfigurationOption(ConfigOption.PRINT_JAVADOC)));

    private final Map<String, String> fieldTypes = new LinkedHashMap<>();
    private final Set<String> classesOfTheFile = new HashSet<>();

    /** For the members of {@code type}, whose fields and nested types are read from it. */
    SameMeaning(TypeDeclaration<?> type) {
        for (FieldDeclaration field : type.getFields()) {
            for (VariableDeclarator variable : field.getVariables()) {
                fieldTypes.put(variable.getNameAsString(), variable.getTypeAsString());
            }
        }
        type.findAll(TypeDeclaration.class).forEach(nested -> classesOfTheFile.add(nested.getNameAsString()));
    }

    static String print(Node node) {
        return PRINTER.print(node);
    }

    /**
     * Puts the member's independent declarations in order, in place, names unchanged: those
     * that {@code like} (ours: the lines of its canonical text, stripped) has, where it has them.
     */
    void order(BodyDeclaration<?> member, List<String> like) {
        LocalNames.canonicalise(member, fieldTypes, classesOfTheFile, like, false);
    }

    /** The canonical text of {@code member} (which is left as it is), ordered as {@link #order} did. */
    String key(BodyDeclaration<?> member, List<String> like) {
        BodyDeclaration<?> copy = member.clone();
        dropModifiersOfLocals(copy);
        dropAllParentheses(copy);
        boolean renamed = LocalNames.canonicalise(copy, fieldTypes, classesOfTheFile, like, true);
        Set<String> declared = new HashSet<>();
        if (!renamed) {
            copy.findAll(VariableDeclarator.class).forEach(v -> declared.add(v.getNameAsString()));
            copy.findAll(Parameter.class).forEach(p -> declared.add(p.getNameAsString()));
        }
        boolean topLevel = copy.findAll(TypeDeclaration.class).isEmpty()
                && copy.findAll(ObjectCreationExpr.class).stream().allMatch(c -> c.getAnonymousClassBody().isEmpty());
        if (topLevel && !(copy instanceof TypeDeclaration<?>)) {
            Set<String> unshadowed = new HashSet<>(fieldTypes.keySet());
            unshadowed.removeAll(declared);
            dropThisBeforeFields(copy, unshadowed);
        }
        parenthesiseFully(copy);
        return print(copy);
    }

    /**
     * The canonical text of a statement of a member: {@code canonicalName} gives the name of a
     * local in scope (null for a name that is not one), {@code fields} the fields of the class.
     */
    static String keyOf(Statement statement, Function<String, String> canonicalName, Set<String> fields) {
        BlockStmt holder = new BlockStmt(new NodeList<>(statement.clone()));
        for (NameExpr name : holder.findAll(NameExpr.class)) {
            String canonical = canonicalName.apply(name.getNameAsString());
            if (canonical != null) {
                name.setName(canonical);
            }
        }
        dropModifiersOfLocals(holder);
        dropAllParentheses(holder);
        dropThisBeforeFields(holder, fields);
        parenthesiseFully(holder);
        return print(holder.getStatement(0));
    }

    /** {@code final} and annotations off every local and parameter (a field's stay: they are members' modifiers). */
    private static void dropModifiersOfLocals(Node root) {
        for (VariableDeclarationExpr declaration : root.findAll(VariableDeclarationExpr.class)) {
            declaration.setModifiers(new NodeList<>());
            declaration.setAnnotations(new NodeList<>());
        }
        for (Parameter parameter : root.findAll(Parameter.class)) {
            parameter.setModifiers(new NodeList<>());
            parameter.setAnnotations(new NodeList<>());
        }
    }

    private static void dropAllParentheses(Node root) {
        for (EnclosedExpr parentheses : root.findAll(EnclosedExpr.class)) {
            parentheses.replace(parentheses.getInner());
        }
    }

    /** {@code this.f} as {@code f}, for the fields named in {@code fields}. */
    private static void dropThisBeforeFields(Node root, Set<String> fields) {
        for (FieldAccessExpr access : root.findAll(FieldAccessExpr.class)) {
            if (access.getScope() instanceof ThisExpr self && self.getTypeName().isEmpty()
                    && fields.contains(access.getNameAsString())) {
                access.replace(new NameExpr(access.getNameAsString()));
            }
        }
    }

    /** Every operator expression that is part of another expression, in parentheses. */
    private static void parenthesiseFully(Node root) {
        List<Expression> expressions = root.findAll(Expression.class);
        for (Expression expression : expressions) {
            boolean operator = expression instanceof BinaryExpr || expression instanceof UnaryExpr
                    || expression instanceof ConditionalExpr || expression instanceof CastExpr
                    || expression instanceof AssignExpr || expression instanceof InstanceOfExpr
                    || expression instanceof LambdaExpr || expression instanceof SwitchExpr;
            if (operator && expression.getParentNode().filter(parent -> parent instanceof Expression).isPresent()) {
                EnclosedExpr parentheses = new EnclosedExpr();
                expression.replace(parentheses);
                parentheses.setInner(expression);
            }
        }
    }
}
