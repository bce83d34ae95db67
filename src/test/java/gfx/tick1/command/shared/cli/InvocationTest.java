package gfx.tick1.command.shared.cli;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class InvocationTest {

    @Test
    void theInstalledLauncherIsTick1() {
        assertThat(Invocation.command("gfx.tick1.Tick1 -i scene.xml", "/opt/tick1/lib/tick1-0.1.0.jar:/opt/tick1/lib/"
                + "picocli-4.7.7.jar")).as("the launcher names the main class").isEqualTo("tick1");
    }

    @Test
    void theJarIsJavaDashJarAndTheJarAsTheUserNamedIt() {
        assertThat(Invocation.command("Downloads/tick1.jar diff Sphere.java", "Downloads/tick1.jar"))
                .isEqualTo("java -jar Downloads/tick1.jar");
        assertThat(Invocation.command("tick1.jar", "tick1.jar")).as("no arguments").isEqualTo("java -jar tick1.jar");
    }

    @Test
    void aJarWhoseNameHasASpaceIsQuoted() {
        assertThat(Invocation.command("C:\\Users\\Zoë\\Tick 1\\tick1.jar", "C:\\Users\\Zoë\\Tick 1\\tick1.jar"))
                .isEqualTo("java -jar \"C:\\Users\\Zoë\\Tick 1\\tick1.jar\"");
    }

    @Test
    void aJarOnTheClassPathWithAMainClassNamedIsNotJavaDashJar() {
        assertThat(Invocation.command("gfx.tick1.Tick1", "tick1.jar")).isEqualTo("tick1");
    }

    @Test
    void theLauncherTakesMoreHeapFromJavaOptsAndTheJarFromMinusXmx() {
        assertThat(Invocation.moreMemory("tick1")).as("the launcher reads JAVA_OPTS").isEqualTo("JAVA_OPTS=-Xmx...");
        assertThat(Invocation.moreMemory("java -jar \"Tick 1/tick1.jar\""))
                .as("java -jar ignores JAVA_OPTS").isEqualTo("java -Xmx... -jar \"Tick 1/tick1.jar\"");
    }
}
