package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;

/**
 * The host's files a run sees: the JDK it runs on and the libraries that JDK loads, nothing else
 * of the host's. Each file is bound into the run's own root file system (bwrap's, in memory) at
 * the path the JVM asks for, with the links on the way to it made there too; the folders around
 * them are the run's own, so a run sees no other name in them, and nothing it looks up there is
 * remembered once it has ended.
 *
 * <p>Before each run the grader reads every one of these files whole ({@link #warm}), so that all
 * their pages are in the host's page cache when the run starts. Every run shares that cache: a run
 * that read some pages of a file no one else reads, or dropped some ({@code posix_fadvise}), would
 * otherwise leave a mark a later run finds by timing its reads, and carry what it knows (a hidden
 * scene) from one grade to the next. After {@link #warm}, the pages a run can time are all in
 * memory, whatever earlier runs did.
 */
final class SystemFiles {

    /** The JDK's parts a run of java uses: the launcher, its libraries and modules, its configuration. */
    private static final List<String> JDK_PARTS = List.of("bin/java", "lib", "conf", "release");
    /** Glibc's ldd, which lists the libraries a program or library loads and where the loader finds them. */
    private static final Path LDD = Path.of("/usr/bin/ldd");
    /** More links than this on the way to one file is a loop. */
    private static final int MOST_LINKS = 40;

    /** A symbolic link of the host's on the way to a file, made the same in the run's root. */
    record Link(Path at, String target) {
    }

    /** The files, each by its real path, where the run sees it too. */
    private final List<Path> files;
    /** The links on the way to them, where the JVM's paths go through links. */
    private final List<Link> links;

    SystemFiles(List<Path> files, List<Link> links) {
        this.files = List.copyOf(files);
        this.links = List.copyOf(links);
    }

    /**
     * The files a run of {@code javaHome}'s java needs: the JDK's launcher, {@code lib} and
     * {@code conf} (the links there into /etc followed), and every library ldd says the launcher
     * and the JDK's libraries load; and {@code programs} with the libraries they load.
     *
     * @throws IOException when the JDK's files cannot be listed or ldd cannot be run
     */
    static SystemFiles of(Path javaHome, List<Path> programs) throws IOException, InterruptedException {
        Set<Path> wanted = new LinkedHashSet<>(programs);
        for (String part : JDK_PARTS) {
            Path path = javaHome.resolve(part);
            if (Files.isDirectory(path, LinkOption.NOFOLLOW_LINKS)) {
                try (var entries = Files.walk(path)) {
                    entries.filter(entry -> !Files.isDirectory(entry, LinkOption.NOFOLLOW_LINKS)).forEach(wanted::add);
                }
            } else {
                wanted.add(path);
            }
        }
        List<Path> loaders = wanted.stream()
                .filter(path -> path.getFileName().toString().endsWith(".so") || path.endsWith("bin/java")
                        || programs.contains(path))
                .filter(Files::isRegularFile).toList();
        wanted.addAll(librariesLoadedBy(loaders));
        return following(wanted);
    }

    /**
     * The files {@code paths} lead to, by their real paths, with the links on the way; none for
     * a path that leads nowhere or to a folder.
     */
    static SystemFiles following(Iterable<Path> paths) throws IOException {
        Set<Path> files = new LinkedHashSet<>();
        Set<Link> links = new LinkedHashSet<>();
        for (Path path : paths) {
            Path real = follow(path.toAbsolutePath().normalize(), links, 0);
            if (real != null && Files.isRegularFile(real, LinkOption.NOFOLLOW_LINKS)) {
                files.add(real);
            }
        }
        return new SystemFiles(new ArrayList<>(files), new ArrayList<>(links));
    }

    /** The real paths of the files, each bound read-only where it really is. */
    List<Path> files() {
        return files;
    }

    /** The paths of the links made on the way to them. */
    List<Path> linkPaths() {
        return links.stream().map(Link::at).toList();
    }

    /**
     * bwrap's arguments that make them in the run's root: the folders that hold the links, the
     * links, and each file bound read-only at its own path (bwrap makes the folders above it).
     */
    List<String> bwrapArguments() {
        List<String> arguments = new ArrayList<>();
        for (Link link : links) {
            Path folder = link.at().getParent();
            if (folder != null && folder.getParent() != null) {
                arguments.addAll(List.of("--dir", folder.toString()));
            }
            arguments.addAll(List.of("--symlink", link.target(), link.at().toString()));
        }
        for (Path file : files) {
            arguments.addAll(List.of("--ro-bind", file.toString(), file.toString()));
        }
        return arguments;
    }

    /**
     * Reads every file whole, so that each page of them is in the host's page cache when the next
     * run starts (a file that is gone or unreadable is skipped: the run will find it missing too).
     */
    void warm() {
        ByteBuffer buffer = ByteBuffer.allocateDirect(1 << 20);
        for (Path file : files) {
            readWhole(file, buffer);
        }
    }

    /** Reads {@code file} to its end through {@code buffer}, and forgets what it read. */
    static void readWhole(Path file, ByteBuffer buffer) {
        try (FileChannel channel = FileChannel.open(file)) {
            do {
                buffer.clear();
            } while (channel.read(buffer) >= 0);
        } catch (IOException e) {
            // Not there or not readable: nothing of it is in memory, and nothing of it can be timed.
        }
    }

    /**
     * The real path of {@code path}, an absolute path without "." or "..", adding to {@code links}
     * each link on the way (by the path it has, whose folders are real); null when it leads nowhere.
     */
    private static Path follow(Path path, Set<Link> links, int depth) throws IOException {
        if (depth > MOST_LINKS) {
            return null;
        }
        Path real = path.getRoot();
        for (Path name : path) {
            Path next = real.resolve(name);
            if (Files.isSymbolicLink(next)) {
                String target = Files.readSymbolicLink(next).toString();
                links.add(new Link(next, target));
                real = follow(real.resolve(target).normalize(), links, depth + 1);
                if (real == null) {
                    return null;
                }
            } else if (Files.exists(next, LinkOption.NOFOLLOW_LINKS)) {
                real = next;
            } else {
                return null;
            }
        }
        return real;
    }

    /**
     * The libraries ldd says {@code programs} load, by the paths the loader opens them at
     * (its own included); none that ldd cannot find.
     */
    private static List<Path> librariesLoadedBy(List<Path> programs) throws IOException, InterruptedException {
        if (programs.isEmpty()) {
            return List.of();
        }
        List<String> command = new ArrayList<>(List.of(LDD.toString()));
        programs.forEach(program -> command.add(program.toString()));
        Process ldd = Sandbox.processFor(command).redirectErrorStream(true).start();
        ldd.getOutputStream().close();
        byte[] said = ldd.getInputStream().readNBytes(1 << 20);
        if (!ldd.waitFor(60, TimeUnit.SECONDS)) {
            ldd.destroyForcibly();
            throw new IOException("ldd did not end");
        }
        List<Path> libraries = new ArrayList<>();
        for (String line : new String(said, StandardCharsets.UTF_8).lines().toList()) {
            // "\tlibz.so.1 => /lib/x86_64-linux-gnu/libz.so.1 (0x...)" and "\t/lib64/ld-linux-x86-64.so.2 (0x...)"
            String entry = line.strip();
            int arrow = entry.indexOf("=> ");
            String where = arrow >= 0 ? entry.substring(arrow + 3) : entry;
            int address = where.lastIndexOf(" (0x");
            if (where.startsWith("/") && address > 0) {
                libraries.add(Path.of(where.substring(0, address)));
            }
        }
        if (libraries.isEmpty()) {
            throw new IOException("ldd listed no library that java loads");
        }
        return libraries;
    }
}
