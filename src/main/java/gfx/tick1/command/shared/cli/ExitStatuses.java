package gfx.tick1.command.shared.cli;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.TreeMap;
import picocli.CommandLine;

/**
 * The statuses every command shares, and each command's "Exit status:" help, built from the
 * {@link ExitStatus} constants of its class and the shared ones it does not word itself.
 */
public final class ExitStatuses {

    /** What the start-up gives any command whose command line picocli rejects. */
    @ExitStatus("the command line is wrong")
    public static final int EXIT_USAGE = 2;

    /** What the start-up gives any command that throws, or that runs out of heap. */
    @ExitStatus("an internal error (a bug: please report it), or Java ran out of memory (give it more with "
            + "JAVA_OPTS=-Xmx...)")
    public static final int EXIT_INTERNAL = 4;

    private ExitStatuses() {
    }

    /**
     * Sets the exit-status help of this command and of all its subcommands, to any depth, from
     * their classes' {@link ExitStatus} constants.
     */
    public static void describe(CommandLine commandLine) {
        Map<Integer, String> statuses = of(commandLine.getCommand().getClass());
        if (!statuses.isEmpty()) {
            Map<String, String> help = new LinkedHashMap<>();
            statuses.forEach((status, meaning) -> help.put(Integer.toString(status), meaning));
            commandLine.getCommandSpec().usageMessage().exitCodeList(help);
        } else {
            // The heading is inherited by every command; one with no statuses shows none.
            commandLine.getCommandSpec().usageMessage().exitCodeListHeading("");
        }
        commandLine.getSubcommands().values().stream().distinct().forEach(ExitStatuses::describe);
    }

    /**
     * The statuses of a command class, lowest first: its own {@link ExitStatus} constants, and the
     * shared ones for numbers it does not word itself. Empty for a class that declares none (such
     * as picocli's help command), whose help then has no exit-status section.
     */
    public static Map<Integer, String> of(Class<?> command) {
        Map<Integer, String> own = declared(command);
        if (own.isEmpty()) {
            return own;
        }
        Map<Integer, String> all = new TreeMap<>(declared(ExitStatuses.class));
        all.putAll(own);
        return all;
    }

    private static Map<Integer, String> declared(Class<?> type) {
        Map<Integer, String> statuses = new TreeMap<>();
        for (Field field : type.getDeclaredFields()) {
            ExitStatus status = field.getAnnotation(ExitStatus.class);
            if (status == null) {
                continue;
            }
            if (!Modifier.isStatic(field.getModifiers()) || field.getType() != int.class) {
                throw new IllegalStateException(field + ": @ExitStatus belongs on a static int constant");
            }
            try {
                field.setAccessible(true);
                String earlier = statuses.put(field.getInt(null), status.value());
                if (earlier != null) {
                    throw new IllegalStateException(field + ": a second meaning for status " + field.getInt(null));
                }
            } catch (IllegalAccessException e) {
                throw new IllegalStateException(e);
            }
        }
        return statuses;
    }
}
