package gfx.tick1;

import gfx.tick1.command.bench.BenchCommand;
import gfx.tick1.command.compare.CompareCommand;
import gfx.tick1.command.coverage.CoverageCommand;
import gfx.tick1.command.diagnose.DiagnoseCommand;
import gfx.tick1.command.diff.DiffCommand;
import gfx.tick1.command.grade.GradeCommand;
import gfx.tick1.command.preview.PreviewCommand;
import gfx.tick1.command.render.CommandLineGuess;
import gfx.tick1.command.render.RenderCommand;
import gfx.tick1.command.render.RenderJob;
import gfx.tick1.command.render.Timings;
import gfx.tick1.command.shared.cli.CommandFailure;
import gfx.tick1.command.shared.cli.ExitStatuses;
import gfx.tick1.command.shared.cli.Invocation;
import gfx.tick1.command.shared.cli.NameEncoding;
import gfx.tick1.command.shared.cli.WholeTokenHelp;
import gfx.tick1.command.shared.grader.vpl.VplCommand;
import gfx.tick1.command.starter.StarterCommand;
import gfx.tick1.engine.scene.Misspelling;
import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;
import picocli.CommandLine.HelpCommand;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.ParseResult;
import picocli.CommandLine.RunLast;
import picocli.CommandLine.UnmatchedArgumentException;
import picocli.CommandLine;

/**
 * Start-up: builds tick1's command line (the render command on top, its subcommands beneath),
 * sets how errors are answered, and runs it. The commands themselves live in their packages,
 * and none of them depends on this class.
 */
public final class Tick1 {

    private Tick1() {
    }

    public static void main(String[] args) {
        Timings.mainStarted();
        Optional<String> lostLetters = NameEncoding.problem(args);
        if (lostLetters.isPresent()) {
            System.err.println(lostLetters.get());
            System.exit(ExitStatuses.EXIT_USAGE);
        }
        // A plain render starts on a guess at its options while picocli reads them (which takes
        // longer than rendering a small frame); the render command checks the guess.
        RenderJob ahead = CommandLineGuess.of(args).filter(guess -> guess.problem().isEmpty()).map(RenderJob::start)
                .orElse(null);
        CommandLine commandLine = commandLine(new RenderCommand(System.out, ahead), args);
        int status;
        try {
            status = commandLine.execute(args);
        } catch (OutOfMemoryError e) {
            // Picocli handles exceptions, not errors; running out of heap is the one a user can fix.
            status = outOfMemory(commandLine.getErr());
        }
        System.exit(status);
    }

    private static int outOfMemory(PrintWriter err) {
        err.println("tick1: Java ran out of memory (it may use " + (Runtime.getRuntime().maxMemory() >> 20)
                + " MiB); give it more with " + Invocation.moreMemory());
        err.flush();
        return ExitStatuses.EXIT_INTERNAL;
    }

    /** A subcommand's name, and how to make it (only when the full command line is built). */
    private record Subcommand(String name, Supplier<Object> command) {
    }

    /** The subcommands, in the order the help lists them. */
    private static final List<Subcommand> SUBCOMMANDS = List.of(new Subcommand("compare", CompareCommand::new),
            new Subcommand("coverage", CoverageCommand::new),
            new Subcommand("diagnose", DiagnoseCommand::new), new Subcommand("diff", DiffCommand::new),
            new Subcommand("grade", GradeCommand::new), new Subcommand("starter", StarterCommand::new),
            new Subcommand("vpl", VplCommand::new),
            new Subcommand("bench", BenchCommand::new), new Subcommand("preview", PreviewCommand::new),
            new Subcommand("help", HelpCommand::new));

    /**
     * The command line for these arguments. Picocli reads every registered command's annotations
     * when it is built, which was the largest part of a 640 x 480 render's start-up; a plain
     * render (options only, no subcommand named, no help asked for) cannot reach a subcommand,
     * so it is built without them. Anything else gets the full command line.
     */
    public static CommandLine commandLine(RenderCommand command, String... args) {
        boolean plainRender = args.length > 0 && args[0].startsWith("-");
        for (String arg : args) {
            boolean asksForHelpOrVersion = arg.equals("--help") || arg.equals("--version")
                    || arg.matches("-[^-]*[hV].*"); // -h, -V, and clusters such as -qh
            boolean namesASubcommand = SUBCOMMANDS.stream().anyMatch(subcommand -> subcommand.name().equals(arg));
            plainRender &= !namesASubcommand && !asksForHelpOrVersion;
        }
        return plainRender ? configure(new CommandLine(command)) : commandLine(command);
    }

    /** The configured command line, as {@link #main} runs it; tests run it the same way. */
    public static CommandLine commandLine(RenderCommand command) {
        CommandLine commandLine = new CommandLine(command);
        // The subcommands inherit --help, --version and the help's layout from the render command.
        SUBCOMMANDS.forEach(subcommand -> commandLine.addSubcommand(subcommand.name(), subcommand.command().get()));
        // In tick1's words, and laid out as the other commands are: picocli's own help command
        // puts a header and a blank line above "Usage:".
        commandLine.getSubcommands().get("help").getCommandSpec().usageMessage().header(new String[0])
                .synopsisHeading("Usage: ")
                .description("Shows the help of tick1, or of the command named (tick1 help grade).");
        return configure(commandLine);
    }

    private static CommandLine configure(CommandLine commandLine) {
        System.setProperty("tick1.cores", Integer.toString(Runtime.getRuntime().availableProcessors()));
        ExitStatuses.describe(commandLine);
        commandLine.setHelpFactory(WholeTokenHelp::new);
        commandLine.setExecutionStrategy(Tick1::runUnlessAWordWasLeftOver);
        commandLine.setCaseInsensitiveEnumValuesAllowed(true);
        // A word starting with @ is a file or folder name (a Moodle folder may be named so), never a
        // file of further arguments.
        commandLine.setExpandAtFiles(false);
        commandLine.setParameterExceptionHandler((reported, args) -> {
            UnmatchedArgumentException leftOver = leftOverWord(reported.getCommandLine());
            ParameterException e = leftOver != null ? leftOver : reported;
            PrintWriter err = e.getCommandLine().getErr();
            String name = e.getCommandLine().getCommandSpec().qualifiedName();
            // One sentence on one line: picocli ends some messages with a full stop of its own (but an
            // ellipsis, as in "-Xmx...", stays whole).
            String message = unknownCommand(e, args);
            if (message == null) {
                message = e.getMessage().replaceAll("(?<!\\.)\\.$", "");
            }
            err.println(name + ": " + message + suggestion(e) + " (see " + Invocation.command()
                    + name.substring("tick1".length()) + " --help)");
            err.flush();
            return ExitStatuses.EXIT_USAGE;
        });
        commandLine.setExecutionExceptionHandler((e, cl, parseResult) -> {
            PrintWriter err = cl.getErr();
            if (e instanceof CommandFailure failure) {
                err.println(cl.getCommandSpec().qualifiedName() + ": " + failure.getMessage());
                err.flush();
                return failure.status();
            }
            for (Throwable cause = e; cause != null; cause = cause.getCause()) {
                if (cause instanceof OutOfMemoryError) {
                    return outOfMemory(err);
                }
            }
            err.println("tick1: internal error: " + e + " (please report this with the scene file)");
            err.flush();
            return ExitStatuses.EXIT_INTERNAL;
        });
        return commandLine;
    }

    /**
     * Runs the last command named, as picocli does, but only if every word was understood:
     * picocli passes over a word it does not know when a subcommand follows it ({@code tick1 foo
     * grade}), where a misspelt word should be an error.
     */
    private static int runUnlessAWordWasLeftOver(ParseResult parseResult) {
        ParseResult last = parseResult;
        while (last.hasSubcommand()) {
            last = last.subcommand();
        }
        UnmatchedArgumentException leftOver = leftOverWord(last.commandSpec().commandLine());
        if (leftOver != null) {
            throw leftOver;
        }
        return new RunLast().execute(parseResult);
    }

    /**
     * The first word that this command or a command before it on the line did not understand, as
     * an error; or null. Named first when a later command also fails, since the later error often
     * follows from it ({@code tick1 compre grade} is not a grade without --sphere).
     */
    private static UnmatchedArgumentException leftOverWord(CommandLine last) {
        List<CommandLine> commands = new ArrayList<>();
        for (CommandLine command = last; command != null; command = command.getParent()) {
            commands.add(0, command);
        }
        for (CommandLine command : commands) {
            if (!command.getUnmatchedArguments().isEmpty()) {
                return new UnmatchedArgumentException(command, command.getUnmatchedArguments());
            }
        }
        return null;
    }

    /**
     * "unknown command 'compar'" for a first word that is neither an option nor a command: picocli
     * words it "Unmatched arguments from index 0: 'compar', 'a', 'b'". Null for any other error.
     */
    private static String unknownCommand(ParameterException e, String[] args) {
        boolean atTheTop = e.getCommandLine().getParent() == null && !e.getCommandLine().getSubcommands().isEmpty();
        if (!atTheTop || !(e instanceof UnmatchedArgumentException unmatched) || unmatched.getUnmatched().isEmpty()) {
            return null;
        }
        String word = unmatched.getUnmatched().get(0);
        return args.length > 0 && args[0].equals(word) && !word.startsWith("-") ? "unknown command '" + word + "'"
                : null;
    }

    /**
     * "; did you mean ...?" for a misspelt option or subcommand, on the error's one line. Picocli's
     * candidates are loose (it offers "bench" for any word with a b, an e and an n); only those a
     * typo or two away are kept.
     */
    private static String suggestion(ParameterException e) {
        if (!(e instanceof UnmatchedArgumentException unmatched) || unmatched.getUnmatched().isEmpty()) {
            return "";
        }
        String word = unmatched.getUnmatched().get(0);
        List<String> close = unmatched.getSuggestions().stream()
                .filter(candidate -> Misspelling.distance(word, candidate) <= Math.max(2, candidate.length() / 3))
                .toList();
        return close.isEmpty() ? "" : "; did you mean " + String.join(" or ", close) + "?";
    }
}
