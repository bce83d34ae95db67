package gfx.tick1.command.shared.grader.sandbox;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The host's files a run sees, how they are made in its root, and that they are in memory when it starts. */
class SystemFilesTest {

    @TempDir
    Path dir;

    private static final Path JDK = Path.of(System.getProperty("java.home")).toAbsolutePath();

    @Test
    void theRunsSeeTheJdksLauncherModulesAndTheLibrariesItLoads() throws Exception {
        Path jdk = JDK.toRealPath();
        List<Path> files = SystemFiles.of(JDK, List.of()).files();

        assertThat(files).as("the files the runs see").contains(jdk.resolve("bin/java"), jdk.resolve("lib/modules"),
                jdk.resolve("lib/server/libjvm.so"));
        assertThat(files).as("the C library java loads")
                .anyMatch(file -> file.getFileName().toString().startsWith("libc.so"));
    }

    @Test
    void theRunsSeeEveryFileOfTheLocaleTheirsIsSetTo() throws Exception {
        Path locale = Path.of("/usr/lib/locale/C.utf8");
        assumeThat(Files.isDirectory(locale)).as("the C.UTF-8 locale is in files (glibc before 2.35, Debian)")
                .isTrue();
        List<Path> localeFiles;
        try (var all = Files.walk(locale)) {
            localeFiles = all.filter(Files::isRegularFile).map(file -> {
                try {
                    return file.toRealPath();
                } catch (IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            }).toList();
        }

        // Without one of them (LC_MESSAGES/SYS_LC_MESSAGES, in a folder of its own) the C library
        // refuses the locale, and Java reads and prints ASCII: every other letter comes out as '?'.
        assertThat(SystemFiles.of(JDK, List.of()).files()).as("the files the runs see")
                .containsAll(localeFiles);
    }

    @Test
    void theRunsSeeNoFileOfTheHostsButTheJdksItsLibrariesAndTheLocales() throws Exception {
        Path jdk = JDK.toRealPath();

        assertThat(SystemFiles.of(JDK, List.of()).files()).as("the files the runs see").allSatisfy(file -> assertThat(
                file.startsWith(jdk) || file.getFileName().toString().contains(".so")
                        || file.startsWith("/etc") || file.startsWith("/usr/lib/locale"))
                .as(file + ": the JDK's, a library, a file of /etc the JDK links to (its configuration) or the "
                        + "locale's").isTrue());
    }

    @Test
    void theRunsSeeNoneOfTick1sOwnCode() throws Exception {
        List<Path> files = SystemFiles.of(JDK, List.of()).files();
        for (String entry : System.getProperty("java.class.path").split(File.pathSeparator)) {
            Path code = Path.of(entry).toAbsolutePath();
            assertThat(files).as("the files the runs see").noneMatch(file -> file.startsWith(code));
        }
    }

    @Test
    void aLinkToAFolderIsMadeInTheRunsRootAndALinkToAFileIsBoundAsTheFile() throws IOException {
        Path real = Files.createDirectories(dir.resolve("usr/lib"));
        Path library = Files.writeString(real.resolve("libz.so.1.2"), "elf");
        Files.createSymbolicLink(real.resolve("libz.so.1"), Path.of("libz.so.1.2"));
        Path lib = Files.createSymbolicLink(dir.resolve("lib"), Path.of("usr/lib"));

        SystemFiles system = SystemFiles.following(List.of(lib.resolve("libz.so.1")));

        assertThat(system.files()).as("the file, by its real path").containsExactly(library.toRealPath());
        Path root = dir.toRealPath();
        assertThat(system.bwrapArguments()).as("bwrap's arguments").containsExactly(
                "--dir", root.toString(), "--symlink", "usr/lib", root.resolve("lib").toString(),
                "--ro-bind", library.toRealPath().toString(), root.resolve("usr/lib/libz.so.1").toString());
    }

    @Test
    void aPathThatLeadsNowhereOrToAFolderShowsNothing() throws IOException {
        Path dangling = Files.createSymbolicLink(dir.resolve("src.zip"), Path.of("missing/src.zip"));
        Path folder = Files.createDirectories(dir.resolve("lib"));

        SystemFiles system = SystemFiles.following(List.of(dangling, folder, dir.resolve("missing.so")));

        assertThat(system.files()).as("the files shown").isEmpty();
    }
}
