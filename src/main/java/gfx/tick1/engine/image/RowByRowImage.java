package gfx.tick1.engine.image;

import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.awt.image.ColorModel;
import java.awt.image.Raster;
import java.awt.image.RenderedImage;
import java.awt.image.SampleModel;
import java.awt.image.WritableRaster;
import java.util.Vector;

/**
 * An image whose rows are still being drawn, for a PNG writer to encode while the last rows are
 * rendered: ImageIO's PNG writer asks a {@link RenderedImage} for its rows one at a time, top to
 * bottom ({@link #getData(Rectangle)}), and each request waits here until every row down to the
 * one asked for is {@linkplain #rowDone done}. The pixels are those of the image it wraps, which
 * only the renderer writes, each row once and before it is declared done.
 *
 * <p>It is tiled a row a tile, so that a writer that reads whole tiles (newer JDKs' PNG writer
 * reads a one-tile image's tile at once) also gets the rows one at a time.
 */
public final class RowByRowImage implements RenderedImage {

    private final BufferedImage image;
    private final boolean[] done;
    /** Rows 0 to ready - 1 are all done. */
    private int ready;
    private String failure;

    public RowByRowImage(BufferedImage image) {
        this.image = image;
        this.done = new boolean[image.getHeight()];
    }

    /** Row y is drawn (and will not change). */
    public synchronized void rowDone(int y) {
        done[y] = true;
        int before = ready;
        while (ready < done.length && done[ready]) {
            ready++;
        }
        if (ready > before) {
            notifyAll();
        }
    }

    /** The rows that are not drawn will never be: a reader waiting for them gets an exception. */
    public synchronized void abandon(String why) {
        failure = why;
        notifyAll();
    }

    /** Waits until rows 0 to {@code rows} - 1 are done. */
    private synchronized void awaitRows(int rows) {
        boolean interrupted = false;
        while (ready < rows && failure == null) {
            try {
                wait();
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        if (ready < rows) {
            throw new IllegalStateException("the image was not finished: " + failure);
        }
    }

    @Override
    public Raster getData(Rectangle rect) {
        awaitRows(Math.min(done.length, rect.y + rect.height));
        return image.getData(rect);
    }

    @Override
    public Raster getData() {
        awaitRows(done.length);
        return image.getData();
    }

    @Override
    public Raster getTile(int tileX, int tileY) {
        awaitRows(tileY + 1);
        return image.getData(new Rectangle(0, tileY, image.getWidth(), 1));
    }

    @Override
    public WritableRaster copyData(WritableRaster raster) {
        awaitRows(done.length);
        return image.copyData(raster);
    }

    @Override
    public Vector<RenderedImage> getSources() {
        return image.getSources();
    }

    @Override
    public Object getProperty(String name) {
        return image.getProperty(name);
    }

    @Override
    public String[] getPropertyNames() {
        return image.getPropertyNames();
    }

    @Override
    public ColorModel getColorModel() {
        return image.getColorModel();
    }

    @Override
    public SampleModel getSampleModel() {
        return image.getSampleModel().createCompatibleSampleModel(image.getWidth(), 1);
    }

    @Override
    public int getWidth() {
        return image.getWidth();
    }

    @Override
    public int getHeight() {
        return image.getHeight();
    }

    @Override
    public int getMinX() {
        return 0;
    }

    @Override
    public int getMinY() {
        return 0;
    }

    @Override
    public int getNumXTiles() {
        return 1;
    }

    @Override
    public int getNumYTiles() {
        return image.getHeight();
    }

    @Override
    public int getMinTileX() {
        return 0;
    }

    @Override
    public int getMinTileY() {
        return 0;
    }

    @Override
    public int getTileWidth() {
        return image.getWidth();
    }

    @Override
    public int getTileHeight() {
        return 1;
    }

    @Override
    public int getTileGridXOffset() {
        return 0;
    }

    @Override
    public int getTileGridYOffset() {
        return 0;
    }
}
