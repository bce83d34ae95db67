package gfx.tick1.command.shared.coverage;

import gfx.tick1.engine.scene.Scene;

/** A scene whose coverage is asked for, with the name a report gives it ("tick1.xml", a file's path). */
public record NamedScene(String name, Scene scene) {
}
