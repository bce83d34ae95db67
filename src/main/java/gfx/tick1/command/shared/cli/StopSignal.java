package gfx.tick1.command.shared.cli;

import java.lang.reflect.InvocationHandler;
import java.lang.reflect.Proxy;

/**
 * SIGTERM ends tick1 as Ctrl-C does, with the status that a command's help gives a stop. Java ends on either
 * signal by running its shutdown hooks (where a command says that it was stopped, and cleans up) and then exits
 * with 128 plus the signal's number: 130 for Ctrl-C (SIGINT), but 143 for SIGTERM. Here SIGTERM calls
 * {@code System.exit} with the command's status instead, which runs the same hooks. Java offers this only through
 * {@code sun.misc.Signal} (module jdk.unsupported), reached by reflection: named in the code, javac would warn of
 * it on every build, with no way to say that it is meant. Where a Java has no such class, SIGTERM keeps Java's
 * own status.
 */
public final class StopSignal {

    private StopSignal() {
    }

    /** From now on, SIGTERM ends this JVM as {@code System.exit(status)} does. */
    public static void exitOnSigterm(int status) {
        try {
            Class<?> signal = Class.forName("sun.misc.Signal");
            Class<?> handlerType = Class.forName("sun.misc.SignalHandler");
            InvocationHandler exit = (proxy, method, args) -> {
                if (method.getDeclaringClass() == Object.class) {
                    return switch (method.getName()) {
                        case "equals" -> proxy == args[0];
                        case "hashCode" -> System.identityHashCode(proxy);
                        default -> "exit " + status + " on SIGTERM";
                    };
                }
                System.exit(status);
                return null;
            };
            Object handler = Proxy.newProxyInstance(handlerType.getClassLoader(), new Class<?>[] {handlerType}, exit);
            signal.getMethod("handle", signal, handlerType).invoke(null,
                    signal.getConstructor(String.class).newInstance("TERM"), handler);
        } catch (ReflectiveOperationException | IllegalArgumentException | SecurityException e) {
            // No sun.misc.Signal, or no SIGTERM to handle here (-Xrs): Java's own ending stands.
        }
    }
}
