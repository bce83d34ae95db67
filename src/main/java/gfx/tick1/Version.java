package gfx.tick1;

import picocli.CommandLine.IVersionProvider;

/** {@code --version}: the build's version from the jar manifest, and the Java it runs on. */
final class Version implements IVersionProvider {

    @Override
    public String[] getVersion() {
        String version = Tick1.class.getPackage().getImplementationVersion();
        return new String[] {
            "tick1 " + (version == null ? "(development build)" : version),
            "Java " + System.getProperty("java.version") + " (" + System.getProperty("java.vm.name") + ")"};
    }
}
