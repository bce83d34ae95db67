package gfx.tick1.command.shared.grader.sandbox;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.sandbox.SeccompFilter.Processes;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * What the sandbox's seccomp filter answers each call, read by running its program as the kernel
 * would on the call's {@code struct seccomp_data}, for each architecture tick1 has a filter for.
 */
class SeccompFilterTest {

    /** seccomp's answers (linux/seccomp.h): the call goes on, fails with EOPNOTSUPP, or kills its process. */
    private static final int ALLOW = 0x7fff0000, REFUSED = 0x00050000 | 95, KILL_PROCESS = 0x80000000;
    /** madvise's advice (linux/mman-common.h). */
    private static final int MADV_DONTNEED = 4, MADV_HUGEPAGE = 14;
    /** AUDIT_ARCH_I386 (linux/audit.h): a 32-bit program's calls, on either machine. */
    private static final int I386 = 0x40000003;

    /**
     * The numbers of the calls the tests make, from the kernel's tables: x86-64's
     * arch/x86/entry/syscalls/syscall_64.tbl, AArch64's include/uapi/asm-generic/unistd.h.
     */
    record Machine(String osArch, int audit, int read, int openat, int mmap, int ioctl, int fallocate,
            int madvise, int pipe2, int socket, int socketpair, int memfdCreate,
            int cloneCall, int clone3Call, int pidfdOpen, int fork) {

        /** What the filter answers this machine's call {@code number} with these arguments. */
        int answer(int number, long... arguments) {
            return answerOf(audit, number, arguments);
        }

        int answerOf(int architecture, int number, long... arguments) {
            byte[] filter = SeccompFilter.forArchitecture(osArch, SceneBatch.PUBLIC, Processes.REFUSED);
            return run(filter, architecture, number, arguments);
        }

        @Override
        public String toString() {
            return osArch;
        }
    }

    static Stream<Machine> machines() {
        return Stream.of(new Machine("amd64", 0xc000003e, 0, 257, 9, 16, 285, 28, 293, 41, 53, 319, 56, 435, 434, 57),
                new Machine("aarch64", 0xc00000b7, 63, 56, 222, 29, 47, 233, 59, 198, 199, 279, 220, 435, 434, -1));
    }

    /** The answers to starting a process (EPERM) and to clone3 (ENOSYS, on which glibc uses clone). */
    private static final int NOT_PERMITTED = 0x00050000 | 1, NO_SUCH_CALL = 0x00050000 | 38;
    /** clone's flags as glibc's pthread_create gives them (a thread), and as its posix_spawn does (a process). */
    private static final long THREAD = 0x3d0f00, SPAWN = 0x4111, CLONE_PIDFD = 0x1000;

    @ParameterizedTest(name = "{0}")
    @MethodSource("machines")
    void noRunCanStartAProcessButEveryRunMayStartThreads(Machine machine) {
        for (SceneBatch batch : SceneBatch.values()) {
            byte[] filter = SeccompFilter.forArchitecture(machine.osArch(), batch, Processes.REFUSED);
            String run = batch == SceneBatch.HIDDEN ? " in a hidden run" : " in a public run";
            assertThat(run(filter, machine.audit(), machine.cloneCall(), THREAD)).as("clone of a thread" + run)
                    .isEqualTo(ALLOW);
            assertThat(run(filter, machine.audit(), machine.cloneCall(), SPAWN)).as("clone of a process" + run)
                    .isEqualTo(NOT_PERMITTED);
            assertThat(run(filter, machine.audit(), machine.cloneCall(), THREAD | CLONE_PIDFD))
                    .as("clone of a thread with a pidfd" + run).isEqualTo(NOT_PERMITTED);
            assertThat(run(filter, machine.audit(), machine.clone3Call(), 0, 88)).as("clone3" + run)
                    .isEqualTo(NO_SUCH_CALL);
            assertThat(run(filter, machine.audit(), machine.pidfdOpen(), 1, 0)).as("pidfd_open" + run)
                    .isEqualTo(NOT_PERMITTED);
            if (machine.fork() >= 0) {
                assertThat(run(filter, machine.audit(), machine.fork())).as("fork" + run).isEqualTo(NOT_PERMITTED);
            }
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("machines")
    void aFilterThatLetsRunsStartProcessesAllowsCloneOfAProcess(Machine machine) {
        byte[] filter = SeccompFilter.forArchitecture(machine.osArch(), SceneBatch.PUBLIC, Processes.ALLOWED);
        assertThat(run(filter, machine.audit(), machine.cloneCall(), SPAWN)).as("clone of a process").isEqualTo(ALLOW);
        assertThat(run(filter, machine.audit(), machine.clone3Call(), 0, 88)).as("clone3").isEqualTo(ALLOW);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("machines")
    void aHiddenRunCannotMakeThePipesSocketsAndMemfdsTheKernelNumbersForTheWholeMachine(Machine machine) {
        byte[] hidden = SeccompFilter.forArchitecture(machine.osArch(), SceneBatch.HIDDEN, Processes.REFUSED);
        assertThat(run(hidden, machine.audit(), machine.pipe2(), 0, 0)).as("pipe2 in a hidden run").isEqualTo(REFUSED);
        assertThat(run(hidden, machine.audit(), machine.socket(), 1, 1, 0)).as("socket in a hidden run")
                .isEqualTo(REFUSED);
        assertThat(run(hidden, machine.audit(), machine.memfdCreate(), 0, 0)).as("memfd_create in a hidden run")
                .isEqualTo(REFUSED);
        // The JVM's file I/O makes one socket pair as it starts.
        assertThat(run(hidden, machine.audit(), machine.socketpair(), 1, 1, 0, 0)).as("socketpair in a hidden run")
                .isEqualTo(ALLOW);
        assertThat(run(hidden, machine.audit(), machine.read(), 3, 0, 4096)).as("read in a hidden run")
                .isEqualTo(ALLOW);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("machines")
    void theOtherRunsMayMakePipesAndSockets(Machine machine) {
        assertThat(machine.answer(machine.pipe2(), 0, 0)).as("pipe2").isEqualTo(ALLOW);
        assertThat(machine.answer(machine.socket(), 1, 1, 0)).as("socket").isEqualTo(ALLOW);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("machines")
    void theAdviceTheJvmGivesIsAllowed(Machine machine) {
        assertThat(machine.answer(machine.madvise, 0x7f0000000000L, 1 << 20, MADV_DONTNEED))
                .as("madvise(MADV_DONTNEED)").isEqualTo(ALLOW);
        assertThat(machine.answer(machine.madvise, 0x7f0000000000L, 1 << 21, MADV_HUGEPAGE))
                .as("madvise(MADV_HUGEPAGE)").isEqualTo(ALLOW);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("machines")
    void readingAndMappingFilesIsAllowed(Machine machine) {
        assertThat(machine.answer(machine.read, 3, 0x1000, 4096)).as("read").isEqualTo(ALLOW);
        assertThat(machine.answer(machine.openat, -100, 0x1000, 0)).as("openat").isEqualTo(ALLOW);
        assertThat(machine.answer(machine.mmap, 0, 4096, 1, 2, 3, 0)).as("mmap").isEqualTo(ALLOW);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("machines")
    void reservingDiskSpaceWithFallocateIsRefused(Machine machine) {
        assertThat(machine.answer(machine.fallocate, 3, 1 /* FALLOC_FL_KEEP_SIZE */, 0, 1L << 30))
                .as("fallocate --keep-size").isEqualTo(REFUSED);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("machines")
    void theIoctlsThatReserveDiskSpaceAreRefusedAndOthersAllowed(Machine machine) {
        assertThat(machine.answer(machine.ioctl, 3, 0x4030582b /* FS_IOC_RESVSP64 */, 0))
                .as("ioctl FS_IOC_RESVSP64").isEqualTo(REFUSED);
        assertThat(machine.answer(machine.ioctl, 0, 0x5401 /* TCGETS */, 0)).as("ioctl TCGETS").isEqualTo(ALLOW);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("machines")
    void aCallOfAnotherArchitectureKillsItsProcess(Machine machine) {
        assertThat(machine.answerOf(I386, 3 /* i386's read */, 3, 0x1000, 4096))
                .as("a 32-bit program's read").isEqualTo(KILL_PROCESS);
    }

    /** Offsets in struct seccomp_data (linux/seccomp.h): int nr; u32 arch; u64 instruction_pointer; u64 args[6]. */
    private static final int NUMBER = 0, ARCHITECTURE = 4, ARGUMENTS = 16;

    /**
     * Runs a classic BPF program (struct sock_filter, little-endian) on one call's seccomp_data, as
     * the kernel would, for the instructions the filter uses; any other fails the test.
     */
    static int run(byte[] program, int architecture, int number, long... arguments) {
        ByteBuffer data = ByteBuffer.allocate(ARGUMENTS + 6 * Long.BYTES).order(ByteOrder.LITTLE_ENDIAN);
        data.putInt(NUMBER, number).putInt(ARCHITECTURE, architecture);
        for (int i = 0; i < arguments.length; i++) {
            data.putLong(ARGUMENTS + i * Long.BYTES, arguments[i]);
        }
        ByteBuffer code = ByteBuffer.wrap(program).order(ByteOrder.LITTLE_ENDIAN);
        int accumulator = 0;
        for (int pc = 0; pc < program.length / 8; pc++) {
            int op = code.getShort(pc * 8) & 0xffff, ifTrue = code.get(pc * 8 + 2) & 0xff;
            int ifFalse = code.get(pc * 8 + 3) & 0xff, k = code.getInt(pc * 8 + 4);
            switch (op) {
                case 0x20 -> accumulator = data.getInt(k);                           // BPF_LD | BPF_W | BPF_ABS
                case 0x54 -> accumulator &= k;                                       // BPF_ALU | BPF_AND | BPF_K
                case 0x15 -> pc += accumulator == k ? ifTrue : ifFalse;              // BPF_JMP | BPF_JEQ | BPF_K
                case 0x35 -> pc += Integer.compareUnsigned(accumulator, k) >= 0 ? ifTrue : ifFalse; // BPF_JGE
                case 0x06 -> {                                                       // BPF_RET | BPF_K
                    return k;
                }
                default -> throw new AssertionError("instruction " + pc + ": opcode 0x" + Integer.toHexString(op)
                        + " is not one the filter uses");
            }
        }
        throw new AssertionError("the program ran off its end");
    }
}
