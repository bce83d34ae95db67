package gfx.tick1.command.shared.javacode;

import com.github.javaparser.ast.Node;
import com.github.javaparser.ast.NodeList;
import com.github.javaparser.ast.body.BodyDeclaration;
import com.github.javaparser.ast.body.CallableDeclaration;
import com.github.javaparser.ast.body.ConstructorDeclaration;
import com.github.javaparser.ast.body.MethodDeclaration;
import com.github.javaparser.ast.body.Parameter;
import com.github.javaparser.ast.body.TypeDeclaration;
import com.github.javaparser.ast.body.VariableDeclarator;
import com.github.javaparser.ast.expr.LambdaExpr;
import com.github.javaparser.ast.expr.NameExpr;
import com.github.javaparser.ast.expr.ObjectCreationExpr;
import com.github.javaparser.ast.expr.PatternExpr;
import com.github.javaparser.ast.expr.SimpleName;
import com.github.javaparser.ast.expr.SwitchExpr;
import com.github.javaparser.ast.expr.VariableDeclarationExpr;
import com.github.javaparser.ast.stmt.BlockStmt;
import com.github.javaparser.ast.stmt.CatchClause;
import com.github.javaparser.ast.stmt.ExpressionStmt;
import com.github.javaparser.ast.stmt.ForEachStmt;
import com.github.javaparser.ast.stmt.ForStmt;
import com.github.javaparser.ast.stmt.LocalClassDeclarationStmt;
import com.github.javaparser.ast.stmt.LocalRecordDeclarationStmt;
import com.github.javaparser.ast.stmt.Statement;
import com.github.javaparser.ast.stmt.SwitchEntry;
import com.github.javaparser.ast.stmt.SwitchStmt;
import com.github.javaparser.ast.stmt.TryStmt;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The local variables and parameters of one member, followed through their scopes as Java
 * defines them (a local's scope starts at its declarator and ends with its block; a parameter's
 * is the whole method). Two things a renaming or a reordering cannot change the meaning of are
 * made canonical here:
 * <ul>
 * <li>every local and parameter is named by the order of its declaration ({@code #1}, {@code #2},
 *     ...; no Java name has a {@code #}), so consistently renamed members print alike;</li>
 * <li>in each run of consecutive declarations {@code T x = e;} whose initialisers have no side
 *     effects ({@link PureExpressions}) and do not name one another's variables, the declarations
 *     are put in one order: a topological order of their uses of each other, the smallest
 *     canonical text first.</li>
 * </ul>
 * A member with a construct whose scopes are not followed here (a local or anonymous class, a
 * pattern, try-with-resources, a nested type, a name as a case label) is left as it is.
 */
final class LocalNames {

    /** One local or parameter in scope: its name by order of declaration, and its declared type. */
    private record Local(String canonical, String type) {
    }

    private final Map<String, String> fieldTypes;
    private final Set<String> classesOfTheFile;
    private final List<String> preferred;
    private final boolean rename;
    private final Deque<Map<String, Local>> scopes = new ArrayDeque<>();
    private int declared;

    private LocalNames(Map<String, String> fieldTypes, Set<String> classesOfTheFile, List<String> preferred,
            boolean rename) {
        this.fieldTypes = fieldTypes;
        this.classesOfTheFile = classesOfTheFile;
        this.preferred = preferred;
        this.rename = rename;
    }

    /**
     * Puts the independent declarations of {@code member} in order and, if {@code rename}, names
     * its locals and parameters by the order of declaration, in place.
     *
     * @param preferred the lines of the canonical text of the member to be like (ours), stripped:
     *                  a declaration whose canonical line is one of them goes where it goes there;
     *                  others keep the order of the source
     * @return false (and nothing changed) when the member holds a construct not followed here
     */
    static boolean canonicalise(BodyDeclaration<?> member, Map<String, String> fieldTypes,
            Set<String> classesOfTheFile, List<String> preferred, boolean rename) {
        if (!followed(member)) {
            return false;
        }
        new LocalNames(fieldTypes, classesOfTheFile, preferred, rename).walk(member);
        return true;
    }

    /** Whether every scope in the member is one this class follows. */
    static boolean followed(BodyDeclaration<?> member) {
        return member instanceof CallableDeclaration<?>
                && member.findAll(LocalClassDeclarationStmt.class).isEmpty()
                && member.findAll(LocalRecordDeclarationStmt.class).isEmpty()
                && member.findAll(PatternExpr.class).isEmpty()
                && member.findAll(TypeDeclaration.class).isEmpty()
                && member.findAll(ObjectCreationExpr.class).stream().allMatch(c -> c.getAnonymousClassBody().isEmpty())
                && member.findAll(TryStmt.class).stream().allMatch(t -> t.getResources().isEmpty())
                // A name as a case label may be an enum constant, which no local can shadow.
                && member.findAll(SwitchEntry.class).stream()
                        .allMatch(entry -> entry.getLabels().stream().noneMatch(label -> label instanceof NameExpr));
    }

    private void walk(Node node) {
        if (node instanceof CallableDeclaration<?> callable) {
            inScope(() -> {
                callable.getParameters().forEach(this::declare);
                if (callable instanceof MethodDeclaration method) {
                    method.getBody().ifPresent(this::walk);
                } else if (callable instanceof ConstructorDeclaration constructor) {
                    walk(constructor.getBody());
                }
            });
        } else if (node instanceof BlockStmt block) {
            inScope(() -> {
                NodeList<Statement> statements = block.getStatements();
                int runEnd = 0;
                for (int i = 0; i < statements.size(); i++) {
                    if (i >= runEnd) {
                        runEnd = orderRunAt(statements, i);
                    }
                    walk(statements.get(i));
                }
            });
        } else if (node instanceof VariableDeclarationExpr declaration) {
            for (VariableDeclarator variable : declaration.getVariables()) {
                declare(variable.getName(), variable.getTypeAsString());
                variable.getInitializer().ifPresent(this::walk);
            }
        } else if (node instanceof ForEachStmt loop) {
            walk(loop.getIterable());
            inScope(() -> {
                walk(loop.getVariable());
                walk(loop.getBody());
            });
        } else if (node instanceof LambdaExpr lambda) {
            inScope(() -> {
                lambda.getParameters().forEach(this::declare);
                walk(lambda.getBody());
            });
        } else if (node instanceof CatchClause clause) {
            inScope(() -> {
                declare(clause.getParameter());
                walk(clause.getBody());
            });
        } else if (node instanceof ForStmt || node instanceof SwitchStmt || node instanceof SwitchExpr) {
            // The for's initialisers, and the declarations of a switch block, reach to its end.
            inScope(() -> List.copyOf(node.getChildNodes()).forEach(this::walk));
        } else if (node instanceof NameExpr name) {
            Local local = lookUp(name.getNameAsString());
            if (local != null && rename) {
                name.setName(local.canonical());
            }
        } else {
            List.copyOf(node.getChildNodes()).forEach(this::walk);
        }
    }

    private void inScope(Runnable body) {
        scopes.push(new HashMap<>());
        body.run();
        scopes.pop();
    }

    private void declare(Parameter parameter) {
        declare(parameter.getName(), parameter.getTypeAsString() + (parameter.isVarArgs() ? "[]" : ""));
    }

    private void declare(SimpleName name, String type) {
        Local local = new Local("#" + ++declared, type);
        scopes.peek().put(name.getIdentifier(), local);
        if (rename) {
            name.setIdentifier(local.canonical());
        }
    }

    private Local lookUp(String name) {
        for (Map<String, Local> scope : scopes) {
            Local local = scope.get(name);
            if (local != null) {
                return local;
            }
        }
        return null;
    }

    /** The declared type of what a bare name means here: a local or parameter, else a field. */
    private String typeOf(String name, Map<String, Local> alsoInScope) {
        Local local = alsoInScope.containsKey(name) ? alsoInScope.get(name) : lookUp(name);
        return local != null ? local.type() : fieldTypes.get(name);
    }

    /**
     * Puts the run of independent side-effect-free declarations that starts at {@code start} (the
     * statements before it already walked) into canonical order.
     *
     * @return the index after the run
     */
    private int orderRunAt(NodeList<Statement> statements, int start) {
        int end = start;
        Map<String, Local> run = new HashMap<>();
        while (end < statements.size() && isPureDeclaration(statements.get(end), run)) {
            VariableDeclarator variable = declarator(statements.get(end));
            run.put(variable.getNameAsString(), new Local(null, variable.getTypeAsString()));
            end++;
        }
        if (end - start > 1) {
            List<Statement> ordered = canonicalOrder(List.copyOf(statements.subList(start, end)));
            for (int i = 0; i < ordered.size(); i++) {
                statements.set(start + i, ordered.get(i).clone());
            }
        }
        return end;
    }

    /** {@code T x = e;}, one variable, with an initialiser free of side effects. */
    private boolean isPureDeclaration(Statement statement, Map<String, Local> run) {
        VariableDeclarator variable = declarator(statement);
        if (variable == null || variable.getInitializer().isEmpty() || run.containsKey(variable.getNameAsString())) {
            return false;
        }
        return new PureExpressions(name -> typeOf(name, run), fieldTypes, classesOfTheFile)
                .isPure(variable.getInitializer().get());
    }

    private static VariableDeclarator declarator(Statement statement) {
        if (statement instanceof ExpressionStmt expression
                && expression.getExpression() instanceof VariableDeclarationExpr declaration
                && declaration.getVariables().size() == 1) {
            return declaration.getVariable(0);
        }
        return null;
    }

    /**
     * Kahn's topological sort of the run: a declaration stays after every declaration whose
     * variable it names (and before one declaring a name it reads as a field's); among those free
     * to go next, the one whose canonical line comes first in {@link #preferred}, else the first
     * in the source.
     */
    private List<Statement> canonicalOrder(List<Statement> run) {
        int count = run.size();
        List<Set<Integer>> before = new ArrayList<>();
        for (int j = 0; j < count; j++) {
            before.add(new HashSet<>());
            for (int i = 0; i < j; i++) {
                if (names(run.get(j)).contains(declarator(run.get(i)).getNameAsString())
                        || names(run.get(i)).contains(declarator(run.get(j)).getNameAsString())) {
                    before.get(j).add(i);
                }
            }
        }
        Map<String, String> emitted = new HashMap<>();
        List<Integer> order = new ArrayList<>();
        while (order.size() < count) {
            String name = "#" + (declared + order.size() + 1);
            int best = -1;
            int bestRank = Integer.MAX_VALUE;
            for (int j = 0; j < count; j++) {
                if (!order.contains(j) && order.containsAll(before.get(j))) {
                    int rank = preferred.indexOf(line(run.get(j), name, emitted));
                    rank = rank < 0 ? Integer.MAX_VALUE - 1 : rank;
                    if (rank < bestRank) {
                        best = j;
                        bestRank = rank;
                    }
                }
            }
            order.add(best);
            emitted.put(declarator(run.get(best)).getNameAsString(), name);
        }
        return order.stream().map(run::get).toList();
    }

    private static Set<String> names(Statement statement) {
        Set<String> names = new HashSet<>();
        statement.findAll(NameExpr.class).forEach(name -> names.add(name.getNameAsString()));
        return names;
    }

    /** The declaration's line of the canonical text were it declared next, as {@code name}. */
    private String line(Statement declaration, String name, Map<String, String> emitted) {
        Statement copy = declaration.clone();
        declarator(copy).setName(name);
        return SameMeaning.keyOf(copy, original -> {
            if (emitted.containsKey(original)) {
                return emitted.get(original);
            }
            Local local = lookUp(original);
            return local == null ? null : local.canonical();
        }, fieldTypes.keySet()).strip();
    }
}
