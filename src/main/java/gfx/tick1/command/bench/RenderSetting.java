package gfx.tick1.command.bench;

import gfx.tick1.engine.scene.Scene;
import java.awt.image.BufferedImage;

/** One way of rendering a frame (a renderer, its samples and threads), as the report names it. */
record RenderSetting(String name, int samples, int threads, Frame frame) {

    /** Renders a scene at a size; parallel streams inside run on the caller's pool. */
    interface Frame {
        BufferedImage render(Scene scene, int width, int height);
    }
}
