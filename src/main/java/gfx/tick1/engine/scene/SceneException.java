package gfx.tick1.engine.scene;

/**
 * A scene file that cannot be rendered. The message is one line that names the file and, where
 * the problem has a place, its line and column: {@code scenes/x.xml:7:5: sphere radius "-1": must
 * be a number greater than 0}. It is unchecked so that {@code new SceneLoader(filename)} keeps
 * the starter code's signature.
 */
public final class SceneException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    public SceneException(String message) {
        super(message, null, false, false);
    }

    public SceneException(String message, Throwable cause) {
        super(message, cause, false, false);
    }
}
