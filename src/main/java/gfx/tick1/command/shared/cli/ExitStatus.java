package gfx.tick1.command.shared.cli;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * What an exit status of a command means, written beside the constant that holds it: the
 * command's "Exit status:" help is built from these (see {@link ExitStatuses}), so that a status
 * is written once, where the code returns it.
 */
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.FIELD)
public @interface ExitStatus {

    /** The meaning, as the help shows it after the number. */
    String value();
}
