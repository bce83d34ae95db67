package gfx.tick1.command.shared.grader.lookalike;

import java.util.List;

/**
 * A side's files as parsed for comparing, before they are cut into tokens: the members compared, in the order
 * compared, each with its canonical text, and what could not be parsed and why. It depends on the files' bytes
 * alone (and on tick1), so it can be kept between runs ({@link ParsedCodes}) and the files not parsed again.
 *
 * @param members the members compared, every one (the cap on tokens is applied when they are cut into tokens)
 * @param notes   what was not compared and why ("Sphere.java does not parse"), one phrase each
 */
public record ParsedCode(List<ComparedCode.Member> members, List<String> notes) {

    public ParsedCode {
        members = List.copyOf(members);
        notes = List.copyOf(notes);
    }
}
