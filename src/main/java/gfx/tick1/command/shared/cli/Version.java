package gfx.tick1.command.shared.cli;

import picocli.CommandLine.IVersionProvider;

/**
 * {@code --version}: the build's version from the jar manifest (its main section, which every
 * package of the jar shares), and the Java it runs on.
 */
public final class Version implements IVersionProvider {

    @Override
    public String[] getVersion() {
        String version = Version.class.getPackage().getImplementationVersion();
        return new String[] {
            "tick1 " + (version == null ? "(development build)" : version),
            "Java " + System.getProperty("java.version") + " (" + System.getProperty("java.vm.name") + ")"};
    }
}
