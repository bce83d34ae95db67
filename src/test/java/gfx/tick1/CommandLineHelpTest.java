package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.bench.BenchCommand;
import gfx.tick1.command.render.RenderCommand;
import gfx.tick1.command.shared.cli.Version;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.junit.jupiter.api.Test;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine;

/** What tick1 --help, tick1 help COMMAND and a mistyped command line tell a newcomer. */
class CommandLineHelpTest {

    /** The commands as the help lists them, the render command first. */
    private static final List<String> COMMANDS =
            List.of("", "compare", "diagnose", "diff", "grade", "starter", "bench", "preview");

    /** Every command, and picocli's help command as tick1 sets it up. */
    private static final List<String> EVERY_HELP =
            List.of("", "compare", "diagnose", "diff", "grade", "starter", "bench", "preview", "help");

    @Command(name = "extra", description = "A command added after the command line was built.")
    static final class ExtraCommand implements Callable<Integer> {
        @Override
        public Integer call() {
            return 0;
        }
    }

    @Test
    void aSubcommandAddedAtRunTimeInheritsHelpVersionAndLayout() {
        CommandLine commandLine = Tick1.commandLine(new RenderCommand());
        commandLine.addSubcommand(new ExtraCommand());
        CommandSpec extra = commandLine.getSubcommands().get("extra").getCommandSpec();
        assertThat(extra.mixinStandardHelpOptions()).as("--help and --version").isTrue();
        assertThat(extra.versionProvider()).as("the version provider").isInstanceOf(Version.class);
        assertThat(extra.usageMessage().sortOptions()).as("options in the order written").isFalse();
        assertThat(extra.usageMessage().autoWidth()).as("the terminal's width").isTrue();
        assertThat(extra.usageMessage().exitCodeListHeading()).isEqualTo("%nExit status:%n");

        StringWriter out = new StringWriter();
        commandLine.setOut(new PrintWriter(out, true));
        assertThat(commandLine.execute("extra", "--version")).isZero();
        assertThat(out.toString()).startsWith("tick1 ");
    }

    @Test
    void everyCommandsHelpListsTheStatusesOfAWrongCommandLineAndOfAnInternalError() {
        for (String command : COMMANDS) {
            String help = help(command);
            assertThat(help).as(command).contains("Exit status:");
            assertThat(help.substring(help.indexOf("Exit status:")))
                    .as(command).containsPattern("\n  2 +\\S").containsPattern("\n  4 +an internal error")
                    .contains("Java ran out of memory");
        }
        assertThat(help("bench"))
                .contains("  " + BenchCommand.EXIT_CANNOT_WRITE + "   the report could not be written");
    }

    @Test
    void helpFollowedByACommandShowsThatCommandsHelp() {
        CliRun run = CliRun.of("help", "grade");
        assertThat(run.status()).as(run.transcript()).isZero();
        assertThat(run.out()).isEqualTo(help("grade"));
    }

    @Test
    void helpAloneShowsTheMainHelp() {
        CliRun run = CliRun.of("help");
        assertThat(run.status()).as(run.transcript()).isZero();
        assertThat(run.out()).isEqualTo(help(""));
    }

    @Test
    void theHelpCommandsOwnHelpHasNoEmptyExitStatusSection() {
        assertThat(help("help")).doesNotContain("Exit status:");
    }

    @Test
    void anUnknownCommandAfterHelpIsOneSentenceOnOneLine() {
        CliRun run = CliRun.of("help", "nosuch");
        assertThat(run.status()).as(run.transcript()).isEqualTo(RenderCommand.EXIT_USAGE);
        assertThat(run.err()).isEqualTo("tick1: Unknown subcommand 'nosuch' (see tick1 --help)"
                + System.lineSeparator());
    }

    @Test
    void anUnknownWordBeforeACommandIsAnErrorNotIgnored() {
        for (String[] args : new String[][] {{"foo", "grade"}, {"foo", "starter", "--out", "x"}}) {
            CliRun run = CliRun.of(args);
            assertThat(run.status()).as(run.transcript()).isEqualTo(RenderCommand.EXIT_USAGE);
            assertThat(run.err()).as(run.transcript()).startsWith("tick1: ").contains("'foo'");
            assertThat(run.err().lines()).hasSize(1);
            assertThat(run.out()).isEmpty();
        }
    }

    @Test
    void aMisspeltCommandOrOptionGetsASuggestionOnItsOneLine() {
        CliRun command = CliRun.of("compre", "a.png", "b.png");
        assertThat(command.status()).isEqualTo(RenderCommand.EXIT_USAGE);
        assertThat(command.err()).contains("did you mean compare?").doesNotContain("preview");
        assertThat(command.err().lines()).hasSize(1);

        assertThat(command.err()).as("the word is a command, not 'arguments from index 0'")
                .isEqualTo("tick1: unknown command 'compre'; did you mean compare? (see tick1 --help)"
                        + System.lineSeparator());

        CliRun option = CliRun.of("--inp", "scene.xml");
        assertThat(option.err()).contains("did you mean --input?").doesNotContain("--intersection");
        assertThat(option.err().lines()).hasSize(1);

        CliRun typoBeforeACommand = CliRun.of("compre", "grade");
        assertThat(typoBeforeACommand.err()).as("the first mistake is named, not grade's missing options")
                .contains("did you mean compare?");
    }

    @Test
    void anUnknownIntersectionMethodIsAnsweredWithTheNamesTheHelpUses() {
        CliRun run = CliRun.of("--intersection", "foo");
        assertThat(run.status()).isEqualTo(RenderCommand.EXIT_USAGE);
        assertThat(run.err()).contains("robust, stable, handout").doesNotContain("ROBUST");
    }

    @Test
    void usageLinesBreakOnlyBetweenTokens() {
        for (String command : COMMANDS) {
            List<String> tokens = synopsisTokens(command, 200);
            for (int width = 55; width <= 120; width++) {
                assertThat(synopsisTokens(command, width)).as("tick1 %s --help at %d columns", command, width)
                        .isEqualTo(tokens);
            }
        }
    }

    /**
     * Wrapping a help to a narrower terminal only moves line breaks to spaces: every word, file
     * name and option (basic_scene.xml, index.html, docs/hard-cases.md, --width=PIXELS) reads as
     * it does on one long line, at every width from picocli's narrowest, 55 columns, to 140.
     */
    @Test
    void everyHelpBreaksLinesOnlyAtSpaces() {
        for (String command : EVERY_HELP) {
            List<String> words = words(ourHelp(command, 1000));
            for (int width = 55; width <= 140; width++) {
                List<String> wrapped = words(ourHelp(command, width));
                assertThat(wrapped).as("%s --help at %d columns splits %s", ("tick1 " + command).strip(), width,
                        firstSplit(wrapped, words)).isEqualTo(words);
            }
        }
    }

    /**
     * Wherever picocli's own layout splits no word, tick1's help below the usage lines is exactly
     * picocli's: breaking only at spaces changes where a line breaks, and nothing else.
     */
    @Test
    void whereNoWordIsSplitTheHelpIsPicoclisOwnLayout() {
        int compared = 0;
        for (String command : EVERY_HELP) {
            CommandLine picocli = command(command);
            picocli.setHelpFactory(CommandLine.Help::new);
            String summary = picocli.getCommandSpec().usageMessage().description()[0].substring(0, 12);
            List<String> words = words(ourHelp(command, 1000));
            for (int width = 55; width <= 140; width++) {
                String theirs = usage(picocli, width);
                if (words(theirs).equals(words)) {
                    String mine = ourHelp(command, width);
                    assertThat(mine.substring(mine.indexOf(summary)))
                            .as("%s --help at %d columns", ("tick1 " + command).strip(), width)
                            .isEqualTo(theirs.substring(theirs.indexOf(summary)));
                    compared++;
                }
            }
        }
        assertThat(compared).as("helps that picocli lays out without splitting a word").isGreaterThan(100);
    }

    @Test
    void theHelpAsPrintedKeepsFileNamesWhole() {
        for (String command : EVERY_HELP) {
            assertThat(help(command)).as("%s --help", ("tick1 " + command).strip())
                    .doesNotContainPattern("\\w\\.\\R\\s*(xml|html|png|csv|md|java|jpg)\\b");
        }
    }

    @Test
    void everyHelpStartsWithItsUsageLine() {
        for (String command : EVERY_HELP) {
            assertThat(help(command)).startsWith(("Usage: tick1 " + command).strip() + " ");
        }
    }

    @Test
    void aMissingDefaultSceneSaysToBeginWithTheStarterKitOrToNameOne() {
        CliRun run = CliRun.of("-q", "-o", "-");
        assertThat(run.status()).as(run.transcript()).isEqualTo(RenderCommand.EXIT_BAD_SCENE);
        assertThat(run.err()).isEqualTo("tick1: basic_scene.xml: no such file (to begin, tick1 starter writes the "
                + "starter kit and its basic_scene.xml into tick1/; or give a scene with -i SCENE.xml; see "
                + "tick1 --help)" + System.lineSeparator());
    }

    @Test
    void theStarterKitGoesToTheHandoutsFolderTick1UnlessToldOtherwise() {
        CommandLine starter = Tick1.commandLine(new RenderCommand()).getSubcommands().get("starter");
        assertThat(starter.getCommandSpec().findOption("--out").defaultValue()).isEqualTo("tick1");
    }

    /**
     * Each command's summary in the top-level help's list fits in two lines at 80 columns, so that
     * the list can be read at a glance.
     */
    @Test
    void theTopLevelListGivesEachCommandAtMostTwoLines() {
        String help = help("");
        String list = help.substring(help.indexOf("Commands:"), help.indexOf("Exit status:"));
        java.util.Map<String, Integer> lines = new java.util.LinkedHashMap<>();
        String current = null;
        for (String line : list.lines().skip(1).toList()) {
            if (line.matches("  \\S.*")) {
                current = line.strip().split("\\s+")[0];
                lines.put(current, 1);
            } else if (current != null && !line.isBlank()) {
                lines.merge(current, 1, Integer::sum);
            }
        }
        assertThat(lines).as("lines per command").isNotEmpty().allSatisfy((name, count) ->
                assertThat(count).as(name).isLessThanOrEqualTo(2));
    }

    /**
     * Each command's own help opens with its summary in at most two lines at 80 columns; the detail
     * follows in paragraphs of its own.
     */
    @Test
    void everyHelpOpensWithASummaryOfAtMostTwoLines() {
        for (String command : COMMANDS) {
            CommandLine target = command(command);
            String summary = target.getCommandSpec().usageMessage().description()[0];
            List<String> lines = usage(target, 80).lines().toList();
            int first = 0;
            while (!lines.get(first).startsWith(summary.substring(0, 20))) {
                first++;
            }
            int count = 0;
            int words = 0;
            while (words < words(summary).size()) {
                words += words(lines.get(first + count)).size();
                count++;
            }
            assertThat(count).as("lines of the summary of %s --help: %s", ("tick1 " + command).strip(),
                    String.join("\n", lines.subList(first, first + count))).isLessThanOrEqualTo(2);
        }
    }

    @Test
    void timingsIsInTheRenderHelp() {
        assertThat(help("")).contains("--timings");
    }

    /** What {@code tick1 COMMAND --help} prints. */
    private static String help(String command) {
        CliRun run = command.isEmpty() ? CliRun.of("--help") : CliRun.of(command, "--help");
        assertThat(run.status()).as(run.transcript()).isZero();
        return run.out();
    }

    private static CommandLine command(String name) {
        CommandLine commandLine = Tick1.commandLine(new RenderCommand());
        return name.isEmpty() ? commandLine : commandLine.getSubcommands().get(name);
    }

    /** The help of {@code target} laid out at this width, without colour. */
    private static String usage(CommandLine target, int width) {
        target.setUsageHelpAutoWidth(false);
        target.setUsageHelpWidth(width);
        return target.getUsageMessage(CommandLine.Help.Ansi.OFF);
    }

    private static List<String> words(String text) {
        return Arrays.asList(text.strip().split("\\s+"));
    }

    /** The first word of {@code wrapped} that is not the word in {@code whole}, and the word after it. */
    private static String firstSplit(List<String> wrapped, List<String> whole) {
        for (int i = 0; i < Math.min(wrapped.size(), whole.size()); i++) {
            if (!wrapped.get(i).equals(whole.get(i))) {
                return "'" + whole.get(i) + "' into '" + wrapped.get(i) + "' / '"
                        + (i + 1 < wrapped.size() ? wrapped.get(i + 1) : "") + "'";
            }
        }
        return "nothing";
    }

    /** The words of the usage lines of {@code tick1 COMMAND --help} at this width. */
    private static List<String> synopsisTokens(String command, int width) {
        String usage = ourHelp(command, width);
        String synopsis = usage.substring(0, usage.indexOf(ourCommand(command).getCommandSpec().usageMessage()
                .description()[0].substring(0, 20)));
        return Arrays.asList(synopsis.trim().split("\\s+"));
    }

    /** Our helps as laid out so far, by command and width: the layout tests read each of them more than once. */
    private static final Map<String, String> OUR_HELPS = new HashMap<>();

    /** The command line of each command whose help {@link #ourHelp} lays out, made once. */
    private static final Map<String, CommandLine> OUR_COMMANDS = new HashMap<>();

    private static synchronized CommandLine ourCommand(String command) {
        return OUR_COMMANDS.computeIfAbsent(command, CommandLineHelpTest::command);
    }

    /** Tick1's help of {@code command} laid out at {@code width}, without colour, laid out once. */
    private static synchronized String ourHelp(String command, int width) {
        return OUR_HELPS.computeIfAbsent(command + " " + width, key -> usage(ourCommand(command), width));
    }
}
