package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.MappedByteBuffer;
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
 * the path the JVM or the loader asks for (a link to a file is bound as the file it leads to),
 * with the links to folders on the way made there too; the folders around them are the run's own,
 * so a run sees no other name in them, and nothing it looks up there is remembered once it has
 * ended.
 *
 * <p>Before each run the grader reads every one of these files whole ({@link #warm}), so that all
 * their pages are in the host's page cache when the run starts. Every run shares that cache: a run
 * that read some pages of a file no one else reads, or dropped some ({@code posix_fadvise}), would
 * otherwise leave a mark a later run finds by timing its reads, and carry what it knows (a hidden
 * scene) from one grade to the next. After {@link #warm}, the pages a run can time are all in
 * memory, whatever earlier runs did.
 */
final class SystemFiles {

    /**
     * The JDK's files a run of the harness uses, headless: the launcher; the modules, with the
     * class data archives (the second for heaps without compressed pointers); the VM and the
     * native libraries of java.base (sockets' included, which find no network), of ImageIO's
     * images (awt, mlib_image, lcms, and the JPEG codec, javajpeg) and of the management the
     * harness reads its CPU time through (with the platform's beans, which ManagementFactory
     * loads); the time zones; the helper that starts processes; and the configuration read at
     * start or by security (javax.crypto's policy files too) and logging. The rest of the JDK (the
     * X11 toolkit, sound, fonts, printing, JFR, the debugger's agents, smart cards, ...) a run
     * never loads, and nothing of it is shown.
     */
    private static final List<String> JDK_FILES = List.of("bin/java", "release", "lib/modules",
            "lib/server/libjvm.so", "lib/server/classes.jsa", "lib/server/classes_nocoops.jsa", "lib/jvm.cfg",
            "lib/libjli.so", "lib/libjava.so", "lib/libjimage.so", "lib/libzip.so", "lib/libnio.so", "lib/libnet.so",
            "lib/libextnet.so",
            "lib/libverify.so", "lib/libjsvml.so", "lib/libmanagement.so", "lib/libmanagement_ext.so", "lib/libawt.so",
            "lib/libawt_headless.so", "lib/libmlib_image.so", "lib/liblcms.so", "lib/libjavajpeg.so", "lib/tzdb.dat",
            "lib/jspawnhelper", "conf/security/java.security",
            "conf/security/policy/unlimited/default_US_export.policy",
            "conf/security/policy/unlimited/default_local.policy",
            "conf/security/policy/limited/default_US_export.policy",
            "conf/security/policy/limited/default_local.policy",
            "conf/security/policy/limited/exempt_local.policy", "conf/logging.properties", "conf/net.properties");
    /** Glibc's files for the runs' locale, C.UTF-8 (built into glibc from 2.35; in these files before). */
    private static final Path LOCALE = Path.of("/usr/lib/locale/C.utf8");
    /** Glibc's ldd, which lists the libraries a program or library loads and where the loader finds them. */
    private static final Path LDD = Path.of("/usr/bin/ldd");
    /** More links than this on the way to one file is a loop. */
    private static final int MOST_LINKS = 40;

    /** A symbolic link of the host's to a folder on the way to a file, made the same in the run's root. */
    record Link(Path at, String target) {
    }

    /** A file of the host's, by its real path, and where the run sees it: the path asked for, its folders real. */
    record Bound(Path real, Path at) {
    }

    /** The files, each by its real path and where the run sees it. */
    private final List<Bound> files;
    /** The links to folders on the way to them, where the paths asked for go through links. */
    private final List<Link> links;
    /** Each file the kernel tells this grader the pages of, mapped (never read through), made by the first warm. */
    private List<Pages> pages;

    /** A file, and its pages mapped where the kernel says which are in memory; null where it would not. */
    private record Pages(Path file, MappedByteBuffer mapped) {
    }

    SystemFiles(List<Bound> files, List<Link> links) {
        this.files = List.copyOf(files);
        this.links = List.copyOf(links);
    }

    /**
     * The files a run of {@code javaHome}'s java needs: the JDK's files the harness uses (the
     * links there into /etc followed), every library ldd says the launcher and those of the JDK
     * load, and the locale's files; and {@code programs} with the libraries they load.
     *
     * @throws IOException when the JDK's files cannot be listed or ldd cannot be run
     */
    static SystemFiles of(Path javaHome, List<Path> programs) throws IOException, InterruptedException {
        Set<Path> wanted = new LinkedHashSet<>(programs);
        JDK_FILES.forEach(file -> wanted.add(javaHome.resolve(file)));
        if (Files.isDirectory(LOCALE)) {
            // Every file, those in its folders too: glibc refuses the locale without LC_MESSAGES/SYS_LC_MESSAGES.
            try (var entries = Files.walk(LOCALE)) {
                entries.filter(Files::isRegularFile).forEach(wanted::add);
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
        Set<Bound> files = new LinkedHashSet<>();
        Set<Link> links = new LinkedHashSet<>();
        for (Path path : paths) {
            Path absolute = path.toAbsolutePath().normalize();
            if (absolute.getParent() == null) {
                continue;
            }
            Set<Link> on = new LinkedHashSet<>();
            Path folder = follow(absolute.getParent(), on, 0);
            Path at = folder == null ? null : folder.resolve(absolute.getFileName());
            Path real = at == null ? null : follow(at, new LinkedHashSet<>(), 0);
            if (real != null && Files.isRegularFile(real, LinkOption.NOFOLLOW_LINKS)) {
                links.addAll(on);
                files.add(new Bound(real, at));
            }
        }
        return new SystemFiles(new ArrayList<>(files), new ArrayList<>(links));
    }

    /** The real paths of the files. */
    List<Path> files() {
        return files.stream().map(Bound::real).distinct().toList();
    }

    /** Where the run sees them, and the links to folders made on the way. */
    List<Path> pathsSeen() {
        List<Path> seen = new ArrayList<>(files.stream().map(Bound::at).toList());
        seen.addAll(links.stream().map(Link::at).toList());
        return seen;
    }

    /**
     * bwrap's arguments that make them in the run's root: the folders that hold the links, the
     * links, and each file bound read-only where the run sees it (bwrap makes the folders above it).
     */
    List<String> bwrapArguments() {
        List<String> arguments = new ArrayList<>();
        Set<Path> folders = new LinkedHashSet<>();
        for (Link link : links) {
            Path folder = link.at().getParent();
            if (folder != null && folder.getParent() != null && folders.add(folder)) {
                arguments.addAll(List.of("--dir", folder.toString()));
            }
            arguments.addAll(List.of("--symlink", link.target(), link.at().toString()));
        }
        for (Bound file : files) {
            arguments.addAll(List.of("--ro-bind", file.real().toString(), file.at().toString()));
        }
        return arguments;
    }

    /**
     * Reads every file whole that may have a page out of memory, so that each page of them is in
     * the host's page cache when the next run starts (a file that is gone or unreadable is
     * skipped: the run will find it missing too). Which pages are in memory the kernel tells
     * ({@code mincore}, through {@link MappedByteBuffer#isLoaded}) only for files this grader could
     * write (as root): those are read only when one of their pages is out; the others always are.
     * And every file of {@code folders} (a run's own, bound read-only: the harness's jar, the class
     * data archive, its scenes), whole: what cannot be listed, the run cannot read either.
     */
    void warm(List<Path> folders) {
        ByteBuffer buffer = ByteBuffer.allocateDirect(1 << 20);
        for (Pages file : pages()) {
            if (file.mapped() == null || !file.mapped().isLoaded()) {
                readWhole(file.file(), buffer);
            }
        }
        for (Path folder : folders) {
            try (var inside = Files.walk(folder)) {
                inside.filter(file -> Files.isRegularFile(file, LinkOption.NOFOLLOW_LINKS))
                        .forEach(file -> readWhole(file, buffer));
            } catch (IOException | java.io.UncheckedIOException e) {
                // A folder the grader made for this run, gone or unreadable: nothing of it to time.
            }
        }
    }

    private synchronized List<Pages> pages() {
        if (pages == null) {
            List<Pages> all = new ArrayList<>();
            for (Path file : files()) {
                all.add(new Pages(file, mapped(file)));
            }
            pages = List.copyOf(all);
        }
        return pages;
    }

    /**
     * {@code file} mapped, read-only, where the kernel says which of its pages are in memory (to a
     * process that may write it); null elsewhere, or where it is empty or cannot be mapped.
     */
    private static MappedByteBuffer mapped(Path file) {
        try (FileChannel channel = FileChannel.open(file)) {
            long size = channel.size();
            return size == 0 || size > Integer.MAX_VALUE || !Files.isWritable(file) ? null
                    : channel.map(FileChannel.MapMode.READ_ONLY, 0, size);
        } catch (IOException | UnsupportedOperationException e) {
            return null;
        }
    }

    /** Reads {@code file} to its end through {@code buffer}, and forgets what it read. */
    private static void readWhole(Path file, ByteBuffer buffer) {
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
