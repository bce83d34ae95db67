package gfx.tick1.command.shared.cli;

import java.util.IllegalFormatException;
import java.util.List;
import java.util.Map;
import picocli.CommandLine.Help;
import picocli.CommandLine.Help.Ansi.Text;
import picocli.CommandLine.Help.Column;
import picocli.CommandLine.Help.TextTable;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;
import picocli.CommandLine.Model.UsageMessageSpec;

/**
 * Picocli's help, with lines broken only between words. Picocli wraps with Java's line
 * BreakIterator, which allows a break after any full stop followed by a letter, and so splits
 * {@code [-i=SCENE.xml]} into {@code [-i=SCENE.} and {@code xml]}, and {@code basic_scene.xml} in
 * a description into {@code basic_scene.} and {@code xml}. A token of the synopsis is one thing to
 * type, and stays on one line; the description, the lists of options, commands and exit statuses,
 * the header and the footer are laid out by picocli in a {@link WholeTokenTable}, which breaks
 * lines only at spaces.
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

    @Override
    public Layout createDefaultLayout(List<OptionSpec> options, List<PositionalParamSpec> positionals,
            ColorScheme colorScheme) {
        Layout layout = super.createDefaultLayout(options, positionals, colorScheme);
        return new Layout(colorScheme, WholeTokenTable.like(layout.textTable(), colorScheme), layout.optionRenderer(),
                layout.parameterRenderer());
    }

    /** The table of the exit statuses: picocli's columns for these keys, wrapped at spaces. */
    @Override
    public TextTable createTextTable(Map<?, ?> map) {
        TextTable table = WholeTokenTable.like(super.createTextTable(map), colorScheme());
        if (map != null) {
            map.forEach((key, value) -> table.addRowValues(format(String.valueOf(key)), format(String.valueOf(value))));
        }
        return table;
    }

    /**
     * The list of commands, as picocli lays it out: each name (with its aliases) and the first line of its
     * header, or else of its description; names take at most half the width.
     */
    @Override
    public String commandList(Map<String, Help> subcommands) {
        if (subcommands.isEmpty()) {
            return "";
        }
        int width = commandSpec().usageMessage().width();
        int names = Math.min(subcommands.keySet().stream().mapToInt(String::length).max().orElse(0), width / 2);
        TextTable table = WholeTokenTable.like(TextTable.forColumns(colorScheme(),
                new Column(names + 2, 2, Column.Overflow.SPAN),
                new Column(width - (names + 2), 2, Column.Overflow.WRAP)), colorScheme());
        table.setAdjustLineBreaksForWideCJKCharacters(adjustCjk());
        subcommands.forEach((name, help) -> {
            UsageMessageSpec usage = help.commandSpec().usageMessage();
            String summary = usage.header().length > 0 ? usage.header()[0]
                    : usage.description().length > 0 ? usage.description()[0] : "";
            Text[] lines = colorScheme().text(format(summary)).splitLines();
            for (int i = 0; i < lines.length; i++) {
                table.addRowValues(i == 0 ? help.commandNamesText(", ") : colorScheme().text(""), lines[i]);
            }
        });
        return table.toString();
    }

    @Override
    public String description(Object... params) {
        return paragraphs(commandSpec().usageMessage().description(), params);
    }

    @Override
    public String header(Object... params) {
        return paragraphs(commandSpec().usageMessage().header(), params);
    }

    @Override
    public String footer(Object... params) {
        return paragraphs(commandSpec().usageMessage().footer(), params);
    }

    /** Lines of text across the whole width, as picocli lays out a description, wrapped at spaces. */
    private String paragraphs(String[] lines, Object... params) {
        if (lines == null) {
            return "";
        }
        ColorScheme scheme = Help.defaultColorScheme(ansi());
        TextTable table = WholeTokenTable.like(TextTable.forColumnWidths(scheme, commandSpec().usageMessage().width()),
                scheme);
        table.setAdjustLineBreaksForWideCJKCharacters(adjustCjk());
        table.indentWrappedLines = 0;
        for (String line : lines) {
            table.addRowValues(format(line, params));
        }
        return table.toString();
    }

    private boolean adjustCjk() {
        return commandSpec().usageMessage().adjustLineBreaksForWideCJKCharacters();
    }

    /** A help text with its {@code %n} and parameters filled in; as written if it is not a format. */
    private static String format(String text, Object... params) {
        try {
            return text == null ? "" : String.format(text, params);
        } catch (IllegalFormatException e) {
            return text;
        }
    }
}
