package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The seccomp filter bubblewrap installs on everything the sandbox runs ({@code bwrap --seccomp}).
 * It refuses the system calls that take disk space a file's size does not show, so that the
 * output folder's count of sizes ({@link OutputCount}) bounds what a run holds on the host's disk:
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
 * A run that renders the organiser's hidden scenes has a stricter filter, which also refuses the
 * calls that make an object the kernel numbers from a count of the whole machine's, and whose
 * number any later run can read: a pipe or a socket (the inode number in its name,
 * {@code pipe:[N]} in /proc/self/fd), a memfd, System V shared memory, a POSIX message queue, an
 * AIO context, userfaultfd. Opening (v + 1) x 100,000 pipes, a hidden run could otherwise leave v
 * for the next grade's public run to read. The render needs none of them; the public run, which
 * compiles, keeps them. Not {@code socketpair}: the JVM makes one as its file I/O starts
 * (sun.nio.ch.FileDispatcherImpl), so native code can still move the count with it; Java's own
 * calls make socket pairs only to start a process, which no run may (below).
 *
 * <p>And no run starts a process: a JVM a run started with options of its own (JVMCI's, to
 * install machine code of its choosing in its code cache; a class data archive it wrote) would
 * run code the harness never chose. Refused with {@code EPERM} ("Operation not permitted"):
 * {@code fork}, {@code vfork} (x86-64 only), {@code clone} whose flags do not make a thread of the
 * same process ({@code CLONE_THREAD}) or that asks for a pidfd ({@code CLONE_PIDFD}), and
 * {@code pidfd_open}; {@code clone3}, whose flags are in memory the filter cannot read, is
 * answered {@code ENOSYS}, on which glibc makes its threads with {@code clone} instead.
 *
 * <p>The rest are answered {@code EOPNOTSUPP} ("Operation not supported"), which glibc's
 * {@code posix_fallocate} meets by writing the bytes (counted by their size). A system call of
 * another architecture than the host's (a 32-bit program, or x32's) kills the process: its
 * numbers are not those below. The JVM and javac use none of the calls refused.
 */
final class SeccompFilter {

    /** Classic BPF as seccomp reads it (linux/filter.h, linux/bpf_common.h). */
    private static final int LOAD_WORD = 0x20, JUMP_EQUAL = 0x15, JUMP_AT_LEAST = 0x35, AND = 0x54, RETURN = 0x06;
    /** seccomp's answers (linux/seccomp.h) and the errno refused calls get. */
    private static final int ALLOW = 0x7fff0000, KILL_PROCESS = 0x80000000, ERRNO = 0x00050000, EOPNOTSUPP = 95,
            EPERM = 1, ENOSYS = 38;
    /**
     * Offsets in struct seccomp_data: the call's number, the architecture, and the low words of the
     * first and second arguments (both machines are little-endian).
     */
    private static final int NUMBER = 0, ARCHITECTURE = 4, FIRST_ARGUMENT = 16, SECOND_ARGUMENT = 24;
    /** clone's flags (linux/sched.h), its first argument on both machines: a thread, and a pidfd for the child. */
    private static final int CLONE_THREAD = 0x00010000, CLONE_PIDFD = 0x00001000;
    /** x86-64's x32 calls have this bit in their number. */
    private static final int X32_BIT = 0x40000000;
    /** An ioctl's type is the second byte of its request: 'X' for the space reservations. */
    private static final int IOCTL_TYPE = 0xff00, RESERVATIONS = 'X' << 8;
    /**
     * One architecture's numbers: AUDIT_ARCH_* (linux/audit.h), ioctl's, those of the calls
     * refused outright, of those refused in hidden runs, and of those that start processes.
     */
    private record Architecture(int audit, int ioctl, int[] refused, int[] numbering, Starting starting) {
    }

    /** The numbers of clone and clone3, which may start a thread, and of the calls that only start a process. */
    private record Starting(int cloneCall, int clone3Call, int[] processes) {
    }

    // The numbers are the kernel's: x86-64's arch/x86/entry/syscalls/syscall_64.tbl, AArch64's
    // include/uapi/asm-generic/unistd.h (ioctl 16 and 29). Refused outright:
    // fallocate, setxattr, lsetxattr, fsetxattr, io_uring_setup, io_uring_enter, io_uring_register, setxattrat.
    // Refused in hidden runs (the kernel's counts of numbered objects): pipe
    // (x86-64 only), pipe2, socket, memfd_create, memfd_secret, io_setup, shmget, mq_open, userfaultfd. Then
    // clone (56 and 220) and clone3 (435); refused as starting a process: fork and vfork (x86-64 only), pidfd_open.
    private static final Architecture X86_64 = new Architecture(0xc000003e, 16,
            new int[] {285, 188, 189, 190, 425, 426, 427, 463},
            new int[] {22, 293, 41, 319, 447, 206, 29, 240, 323}, new Starting(56, 435, new int[] {57, 58, 434}));
    private static final Architecture AARCH64 = new Architecture(0xc00000b7, 29,
            new int[] {47, 5, 6, 7, 425, 426, 427, 463},
            new int[] {59, 198, 279, 447, 0, 194, 180, 282}, new Starting(220, 435, new int[] {434}));

    /** Whether a run may start processes: a grade's never may (see the class's comment). */
    enum Processes { REFUSED, ALLOWED }

    private SeccompFilter() {
    }

    /**
     * The filter for an architecture as Java names it ({@code os.arch}), for {@code batch}, one that
     * lets a run start {@code processes}; or null where tick1 has none.
     */
    static byte[] forArchitecture(String name, SceneBatch batch, Processes processes) {
        return switch (name) {
            case "amd64", "x86_64" -> program(X86_64, batch, processes);
            case "aarch64" -> program(AARCH64, batch, processes);
            default -> null;
        };
    }

    /**
     * The filter as bwrap reads it: struct sock_filter ({@code u16 code; u8 jt, jf; u32 k}) in the
     * machine's byte order, both of whose architectures are little-endian.
     */
    private static byte[] program(Architecture architecture, SceneBatch batch, Processes processes) {
        Program code = new Program();
        code.add(LOAD_WORD, ARCHITECTURE);
        code.jump(JUMP_EQUAL, architecture.audit(), "number", null);
        code.add(RETURN, KILL_PROCESS);
        code.label("number");
        code.add(LOAD_WORD, NUMBER);
        code.jump(JUMP_AT_LEAST, X32_BIT, "refuse", null);
        for (int refused : architecture.refused()) {
            code.jump(JUMP_EQUAL, refused, "refuse", null);
        }
        for (int numbering : batch == SceneBatch.HIDDEN ? architecture.numbering() : new int[0]) {
            code.jump(JUMP_EQUAL, numbering, "refuse", null);
        }
        if (processes == Processes.REFUSED) {
            for (int starting : architecture.starting().processes()) {
                code.jump(JUMP_EQUAL, starting, "not permitted", null);
            }
            code.jump(JUMP_EQUAL, architecture.starting().clone3Call(), "no such call", null);
            code.jump(JUMP_EQUAL, architecture.starting().cloneCall(), "clone", null);
        }
        code.jump(JUMP_EQUAL, architecture.ioctl(), "ioctl", "allow");
        code.label("ioctl");
        code.add(LOAD_WORD, SECOND_ARGUMENT);
        code.add(AND, IOCTL_TYPE);
        code.jump(JUMP_EQUAL, RESERVATIONS, "refuse", "allow");
        code.label("clone");
        // A thread of this process, and no pidfd: (flags & (CLONE_THREAD | CLONE_PIDFD)) == CLONE_THREAD.
        code.add(LOAD_WORD, FIRST_ARGUMENT);
        code.add(AND, CLONE_THREAD | CLONE_PIDFD);
        code.jump(JUMP_EQUAL, CLONE_THREAD, "allow", "not permitted");
        code.label("allow");
        code.add(RETURN, ALLOW);
        code.label("refuse");
        code.add(RETURN, ERRNO | EOPNOTSUPP);
        code.label("not permitted");
        code.add(RETURN, ERRNO | EPERM);
        code.label("no such call");
        code.add(RETURN, ERRNO | ENOSYS);
        return code.bytes();
    }

    /** A program being written, whose jumps name the place they go to (null: the next instruction). */
    private static final class Program {
        private record Instruction(int code, int k, String ifTrue, String ifFalse) {
        }

        private final List<Instruction> instructions = new ArrayList<>();
        private final Map<String, Integer> labels = new HashMap<>();

        void add(int code, int k) {
            jump(code, k, null, null);
        }

        void jump(int code, int k, String ifTrue, String ifFalse) {
            instructions.add(new Instruction(code, k, ifTrue, ifFalse));
        }

        void label(String name) {
            labels.put(name, instructions.size());
        }

        /** The instructions, each jump counted, as the kernel counts it, from the instruction after it. */
        byte[] bytes() {
            ByteBuffer bytes = ByteBuffer.allocate(instructions.size() * 8).order(ByteOrder.LITTLE_ENDIAN);
            for (int i = 0; i < instructions.size(); i++) {
                Instruction instruction = instructions.get(i);
                bytes.putShort((short) instruction.code()).put(offset(instruction.ifTrue(), i))
                        .put(offset(instruction.ifFalse(), i)).putInt(instruction.k());
            }
            return bytes.array();
        }

        private byte offset(String label, int from) {
            int offset = label == null ? 0 : labels.get(label) - (from + 1);
            if (offset < 0 || offset > 0xff) {
                throw new IllegalStateException("a jump to " + label + " of " + offset + " instructions");
            }
            return (byte) offset;
        }
    }

    /**
     * The filter for the host's architecture written to a new file of the grader's alone, deleted
     * when this program ends, for the shell that starts each sandbox to open for bwrap; null where
     * tick1 has none (it then warns). For {@code batch}; with {@link Processes#ALLOWED}, one that lets runs
     * start processes (for the tests that hold the limits against what other programs can do).
     */
    static Path writeForThisMachine(SceneBatch batch, Processes processes) throws IOException {
        byte[] program = forArchitecture(System.getProperty("os.arch", ""), batch, processes);
        if (program == null) {
            return null;
        }
        Path file = Files.createTempFile(Leftovers.prefix("seccomp"), ".bpf",
                PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")));
        file.toFile().deleteOnExit();
        Files.write(file, program);
        return file;
    }
}
