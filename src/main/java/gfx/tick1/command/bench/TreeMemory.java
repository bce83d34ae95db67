package gfx.tick1.command.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The peak of the summed resident memory of a process and every process it starts, as Moodle VPL's jail
 * counts an evaluation against its memory limit: each process's VmRSS read from /proc every
 * {@value #EVERY_MILLIS} ms while the run lasts. A process that lives less than that between two readings
 * may be missed. Where there is no /proc (macOS, Windows) nothing is read and the peak is NaN.
 */
final class TreeMemory {

    private static final long EVERY_MILLIS = 20;
    private static final Path PROC = Path.of("/proc");

    /** Reads nothing: for runs whose memory is not reported, so that no reading thread shares their cores. */
    static TreeMemory none(Process process) {
        return new TreeMemory(null);
    }

    private final Process process;
    private final Thread reader;
    private volatile long peakKibibytes;
    private volatile boolean read;

    private TreeMemory(Process process) {
        this.process = process;
        this.reader = process == null ? null : new Thread(this::readUntilEnd, "tick1-bench-memory");
    }

    /** Starts reading the memory of {@code process} and its descendants until it ends. */
    static TreeMemory of(Process process) {
        TreeMemory memory = new TreeMemory(process);
        if (memory.reader != null && Files.isDirectory(PROC)) {
            memory.reader.setDaemon(true);
            memory.reader.start();
        }
        return memory;
    }

    /** The peak in MiB, once the process has ended; NaN where nothing was read. */
    double peakMebibytes() throws InterruptedException {
        if (reader == null) {
            return Double.NaN;
        }
        reader.join();
        return read ? peakKibibytes / 1024.0 : Double.NaN;
    }

    private void readUntilEnd() {
        try {
            while (process.isAlive()) {
                long sum = residentKibibytes(process.pid())
                        + process.descendants().mapToLong(child -> residentKibibytes(child.pid())).sum();
                peakKibibytes = Math.max(peakKibibytes, sum);
                Thread.sleep(EVERY_MILLIS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** A process's VmRSS in KiB; 0 once it has ended (or for a kernel's thread, which has none). */
    private long residentKibibytes(long pid) {
        try {
            for (String line : Files.readAllLines(PROC.resolve(Long.toString(pid)).resolve("status"))) {
                if (line.startsWith("VmRSS:")) {
                    read = true;
                    return Long.parseLong(line.substring("VmRSS:".length()).replace("kB", "").strip());
                }
            }
        } catch (IOException | RuntimeException e) {
            // Ended between the listing and the reading.
        }
        return 0;
    }
}
