package gfx.tick1.command.shared.javacode;

import com.github.javaparser.ast.expr.BinaryExpr;
import com.github.javaparser.ast.expr.BooleanLiteralExpr;
import com.github.javaparser.ast.expr.CastExpr;
import com.github.javaparser.ast.expr.CharLiteralExpr;
import com.github.javaparser.ast.expr.ConditionalExpr;
import com.github.javaparser.ast.expr.DoubleLiteralExpr;
import com.github.javaparser.ast.expr.EnclosedExpr;
import com.github.javaparser.ast.expr.Expression;
import com.github.javaparser.ast.expr.FieldAccessExpr;
import com.github.javaparser.ast.expr.IntegerLiteralExpr;
import com.github.javaparser.ast.expr.LongLiteralExpr;
import com.github.javaparser.ast.expr.MethodCallExpr;
import com.github.javaparser.ast.expr.NameExpr;
import com.github.javaparser.ast.expr.ObjectCreationExpr;
import com.github.javaparser.ast.expr.ThisExpr;
import com.github.javaparser.ast.expr.UnaryExpr;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;

/**
 * Which expressions are free of side effects, so that two declarations initialised by them may
 * be evaluated in either order: literals, names, arithmetic, and calls of the methods of the
 * classes the student is given and does not edit (Vector3, Ray, RaycastHit, PointLight, Scene,
 * Camera) and of java.lang.Math. A call is known only when the type of what it is called on is:
 * a local, parameter or field of a declared type, or the result of another known call.
 * {@code Scene.findClosestIntersection} is left out (it calls the student's own
 * {@code intersectionWith}), and so is every method of the student's classes.
 */
final class PureExpressions {

    private static final String NUMBER = "a number";
    private static final String MATH = "java.lang.Math";

    /** The given classes' methods without side effects, by class, to the type each returns. */
    private static final Map<String, Map<String, String>> METHODS = Map.of(
            "Vector3", Map.of("add", "Vector3", "subtract", "Vector3", "scale", "Vector3", "cross", "Vector3",
                    "normalised", "Vector3", "reflectIn", "Vector3", "dot", NUMBER, "magnitude", NUMBER,
                    "toRGB", NUMBER),
            "Ray", Map.of("getOrigin", "Vector3", "getDirection", "Vector3", "evaluateAt", "Vector3"),
            "RaycastHit", Map.of("getObjectHit", "Sphere", "getDistance", NUMBER, "getLocation", "Vector3",
                    "getNormal", "Vector3"),
            "PointLight", Map.of("getPosition", "Vector3", "getColour", "Vector3", "getIntensity", NUMBER,
                    "getIlluminationAt", "Vector3"),
            "Scene", Map.of("getAmbientLighting", "Vector3", "getPointLight", "PointLight"),
            "Camera", Map.of("castRay", "Ray"),
            MATH, Map.of("sqrt", NUMBER, "pow", NUMBER, "max", NUMBER, "min", NUMBER, "abs", NUMBER,
                    "cbrt", NUMBER, "hypot", NUMBER, "floor", NUMBER, "ceil", NUMBER, "signum", NUMBER));

    private static final Set<UnaryExpr.Operator> CHANGES_ITS_OPERAND = Set.of(UnaryExpr.Operator.PREFIX_INCREMENT,
            UnaryExpr.Operator.PREFIX_DECREMENT, UnaryExpr.Operator.POSTFIX_INCREMENT,
            UnaryExpr.Operator.POSTFIX_DECREMENT);

    /** The given classes a {@code new} may create without side effects. */
    private static final Set<String> CONSTRUCTED = Set.of("Vector3", "Ray", "RaycastHit", "PointLight");

    private final Function<String, String> typeOfName;
    private final Map<String, String> fieldTypes;
    private final Set<String> classesOfTheFile;

    /**
     * @param typeOfName       the declared type of the local, parameter or field a bare name means, or null
     * @param fieldTypes       the declared type of each field of the class
     * @param classesOfTheFile the class and the nested types the file declares: a class of the
     *                         file named like a given one would be the student's own
     */
    PureExpressions(Function<String, String> typeOfName, Map<String, String> fieldTypes,
            Set<String> classesOfTheFile) {
        this.typeOfName = typeOfName;
        this.fieldTypes = fieldTypes;
        this.classesOfTheFile = classesOfTheFile;
    }

    boolean isPure(Expression expression) {
        return typeOf(expression) != null;
    }

    /** The type of a pure expression, as far as purity needs it; null when it may have side effects. */
    private String typeOf(Expression e) {
        if (e instanceof IntegerLiteralExpr || e instanceof DoubleLiteralExpr || e instanceof LongLiteralExpr
                || e instanceof BooleanLiteralExpr || e instanceof CharLiteralExpr) {
            return NUMBER;
        }
        if (e instanceof NameExpr name) {
            String type = typeOfName.apply(name.getNameAsString());
            boolean math = name.getNameAsString().equals("Math") && !classesOfTheFile.contains("Math");
            return type != null ? type : math ? MATH : null;
        }
        if (e instanceof ThisExpr self && self.getTypeName().isEmpty()) {
            return "this";
        }
        if (e instanceof EnclosedExpr enclosed) {
            return typeOf(enclosed.getInner());
        }
        if (e instanceof UnaryExpr unary) {
            return CHANGES_ITS_OPERAND.contains(unary.getOperator()) ? null
                    : valueOrNull(typeOf(unary.getExpression()));
        }
        if (e instanceof BinaryExpr binary) {
            return typeOf(binary.getLeft()) != null && typeOf(binary.getRight()) != null ? NUMBER : null;
        }
        if (e instanceof ConditionalExpr conditional) {
            return typeOf(conditional.getCondition()) != null && typeOf(conditional.getThenExpr()) != null
                    && typeOf(conditional.getElseExpr()) != null ? NUMBER : null;
        }
        if (e instanceof CastExpr cast) {
            return cast.getType().isPrimitiveType() ? valueOrNull(typeOf(cast.getExpression())) : null;
        }
        if (e instanceof FieldAccessExpr field) {
            return fieldType(field);
        }
        if (e instanceof MethodCallExpr call) {
            return callType(call);
        }
        if (e instanceof ObjectCreationExpr creation) {
            String type = creation.getType().getNameAsString();
            boolean known = CONSTRUCTED.contains(type) && !classesOfTheFile.contains(type)
                    && creation.getScope().isEmpty() && creation.getAnonymousClassBody().isEmpty()
                    && creation.getArguments().stream().allMatch(this::isPure);
            return known ? type : null;
        }
        return null;
    }

    private static String valueOrNull(String type) {
        return type == null ? null : NUMBER;
    }

    /** A component of a Vector3, Math.PI or Math.E, or a field of the student's own object. */
    private String fieldType(FieldAccessExpr field) {
        String scope = typeOf(field.getScope());
        String name = field.getNameAsString();
        if ("Vector3".equals(scope) && !classesOfTheFile.contains("Vector3") && Set.of("x", "y", "z").contains(name)) {
            return NUMBER;
        }
        if (MATH.equals(scope)) {
            return Set.of("PI", "E").contains(name) ? NUMBER : null;
        }
        return "this".equals(scope) ? fieldTypes.get(name) : null;
    }

    private String callType(MethodCallExpr call) {
        if (call.getScope().isEmpty() || !call.getArguments().stream().allMatch(this::isPure)) {
            return null;
        }
        String scope = typeOf(call.getScope().get());
        if (scope == null || classesOfTheFile.contains(scope)) {
            return null;
        }
        return METHODS.getOrDefault(scope, Map.of()).get(call.getNameAsString());
    }
}
