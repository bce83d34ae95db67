package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;

/**
 * The seccomp filter bubblewrap installs on everything the sandbox runs ({@code bwrap --seccomp}):
 * it refuses the system calls that take disk space a file's size does not show, so that the
 * output folder's count of sizes ({@link OutputCount}) bounds what a run holds on the host's disk.
 *
 * <ul>
 *   <li>{@code fallocate(2)}: {@code fallocate --keep-size} reserves any amount with a size of 0;
 *   <li>the {@code ioctl}s of type {@code 'X'}: {@code FS_IOC_RESVSP}, {@code FS_IOC_RESVSP64}
 *       and {@code FS_IOC_ZERO_RANGE} reserve space as fallocate does (Linux's fs/ioctl.c), and
 *       XFS's own ({@code XFS_IOC_ALLOCSP}) did;
 *   <li>{@code setxattr}, {@code lsetxattr}, {@code fsetxattr}, {@code setxattrat}: an extended
 *       attribute takes a block of its own;
 *   <li>{@code io_uring_setup}, {@code io_uring_enter}, {@code io_uring_register}: io_uring
 *       runs fallocate without a system call the filter could see.
 * </ul>
 *
 * Each is answered {@code EOPNOTSUPP} ("Operation not supported"), which glibc's
 * {@code posix_fallocate} meets by writing the bytes (counted by their size). A system call of
 * another architecture than the host's (a 32-bit program, or x32's) kills the process: its
 * numbers are not those above. The JVM and javac use none of these calls.
 */
final class SeccompFilter {

    /** Classic BPF as seccomp reads it (linux/filter.h, linux/bpf_common.h). */
    private static final int LOAD_WORD = 0x20, JUMP_EQUAL = 0x15, JUMP_AT_LEAST = 0x35, AND = 0x54, RETURN = 0x06;
    /** seccomp's answers (linux/seccomp.h) and the errno refused calls get. */
    private static final int ALLOW = 0x7fff0000, KILL_PROCESS = 0x80000000, ERRNO = 0x00050000, EOPNOTSUPP = 95;
    /** Offsets in struct seccomp_data: the call's number, the architecture, the low word of the second argument. */
    private static final int NUMBER = 0, ARCHITECTURE = 4, SECOND_ARGUMENT = 24;
    /** x86-64's x32 calls have this bit in their number. */
    private static final int X32_BIT = 0x40000000;
    /** An ioctl's type is the second byte of its request: 'X' for the space reservations. */
    private static final int IOCTL_TYPE = 0xff00, RESERVATIONS = 'X' << 8;

    /** One architecture's numbers: AUDIT_ARCH_*, ioctl's, and those of the calls refused outright. */
    private record Architecture(int audit, int ioctl, int[] refused) {
    }

    // fallocate, setxattr, lsetxattr, fsetxattr, io_uring_setup, io_uring_enter, io_uring_register, setxattrat
    private static final Architecture X86_64 = new Architecture(0xc000003e, 16,
            new int[] {285, 188, 189, 190, 425, 426, 427, 463});
    private static final Architecture AARCH64 = new Architecture(0xc00000b7, 29,
            new int[] {47, 5, 6, 7, 425, 426, 427, 463});

    private SeccompFilter() {
    }

    /** The filter for the host's architecture, or null where tick1 has none (it then warns). */
    static byte[] forThisMachine() {
        return forArchitecture(System.getProperty("os.arch", ""));
    }

    /** The filter for an architecture as Java names it ({@code os.arch}), or null where tick1 has none. */
    static byte[] forArchitecture(String name) {
        return switch (name) {
            case "amd64", "x86_64" -> program(X86_64);
            case "aarch64" -> program(AARCH64);
            default -> null;
        };
    }

    /**
     * The filter as bwrap reads it: struct sock_filter ({@code u16 code; u8 jt, jf; u32 k}) in the
     * machine's byte order, both of whose architectures are little-endian.
     */
    private static byte[] program(Architecture architecture) {
        List<int[]> code = new ArrayList<>();
        int refused = architecture.refused().length;
        // Jumps count instructions from the next one; the last two are ALLOW and the refusal.
        int allow = 9 + refused, deny = allow + 1;
        code.add(new int[] {LOAD_WORD, 0, 0, ARCHITECTURE});
        code.add(new int[] {JUMP_EQUAL, 1, 0, architecture.audit()});
        code.add(new int[] {RETURN, 0, 0, KILL_PROCESS});
        code.add(new int[] {LOAD_WORD, 0, 0, NUMBER});
        code.add(new int[] {JUMP_AT_LEAST, deny - 5, 0, X32_BIT});
        for (int i = 0; i < refused; i++) {
            code.add(new int[] {JUMP_EQUAL, deny - (6 + i), 0, architecture.refused()[i]});
        }
        code.add(new int[] {JUMP_EQUAL, 0, allow - (6 + refused), architecture.ioctl()});
        code.add(new int[] {LOAD_WORD, 0, 0, SECOND_ARGUMENT});
        code.add(new int[] {AND, 0, 0, IOCTL_TYPE});
        code.add(new int[] {JUMP_EQUAL, 1, 0, RESERVATIONS});
        code.add(new int[] {RETURN, 0, 0, ALLOW});
        code.add(new int[] {RETURN, 0, 0, ERRNO | EOPNOTSUPP});
        ByteBuffer bytes = ByteBuffer.allocate(code.size() * 8).order(ByteOrder.LITTLE_ENDIAN);
        for (int[] instruction : code) {
            bytes.putShort((short) instruction[0]).put((byte) instruction[1]).put((byte) instruction[2])
                    .putInt(instruction[3]);
        }
        return bytes.array();
    }

    /**
     * The filter written to a new file of the grader's alone, deleted when this program ends, for
     * the shell that starts each sandbox to open for bwrap; null where there is no filter.
     */
    static Path writeForThisMachine() throws IOException {
        byte[] program = forThisMachine();
        if (program == null) {
            return null;
        }
        Path file = Files.createTempFile("tick1-seccomp-", ".bpf",
                PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")));
        file.toFile().deleteOnExit();
        Files.write(file, program);
        return file;
    }
}
