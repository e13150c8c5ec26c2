package org.proactiverobotics.sim2d.map;

import java.awt.image.BufferedImage;
import java.awt.image.ColorModel;
import java.awt.image.IndexColorModel;
import java.awt.image.Raster;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import javax.imageio.ImageIO;

/**
 * A map's picture as map_server averages it: for each pixel the mean of its channels on a 0–255 scale,
 * once with the alpha channel among them (how map_server's trinary mode averages) and once without (scale
 * and raw modes); the same numbers when the picture has no alpha. Pixels run row by row from the top,
 * as in the file. PGM (P2, P5) is read by {@link PgmReader}; PNG (and whatever else javax.imageio reads)
 * by javax.imageio.
 *
 * @param width            pixels across
 * @param height           pixels down
 * @param meanWithAlpha    each pixel's mean over every channel, alpha included, 0–255
 * @param meanWithoutAlpha each pixel's mean over the colour channels, 0–255
 */
public record MapImage(int width, int height, double[] meanWithAlpha, double[] meanWithoutAlpha) {

    /** The most pixels a map may have (a 20 000 x 20 000 picture): beyond, the memory of a small machine runs out. */
    static final long MAX_PIXELS = 400_000_000L;

    private static final byte[] PNG_SIGNATURE = {(byte) 0x89, 'P', 'N', 'G'};

    /**
     * @param file a PGM (P2 or P5) or PNG file
     * @return its pixels
     * @throws MapException when it is missing, unreadable, of another format, or inconsistent
     */
    public static MapImage read(Path file) {
        byte[] head = new byte[4];
        int n;
        try (InputStream in = Files.newInputStream(file)) {
            n = in.readNBytes(head, 0, 4);
        } catch (NoSuchFileException e) {
            throw new MapException(file, "no such image file");
        } catch (IOException e) {
            throw new MapException(file, "cannot read the image: " + e.getMessage());
        }
        if (n >= 2 && head[0] == 'P' && (head[1] == '2' || head[1] == '5')) {
            return PgmReader.read(file);
        }
        if (n >= 2 && head[0] == 'P' && head[1] >= '1' && head[1] <= '7') {
            throw new MapException(file, "a Netpbm P" + (char) head[1] + " image: only PGM (P2, P5) and PNG are read");
        }
        if (n < 4 || !java.util.Arrays.equals(head, PNG_SIGNATURE)) {
            throw new MapException(file, "wrong magic number: neither a PGM (P2, P5) nor a PNG image");
        }
        BufferedImage image;
        try {
            image = ImageIO.read(file.toFile());
        } catch (IOException e) {
            throw new MapException(file, "not a readable PNG: " + e.getMessage());
        }
        if (image == null) {
            throw new MapException(file, "not a readable PNG");
        }
        return of(image);
    }

    /** The means of a decoded picture; a palette picture is averaged on its colours, not its indices. */
    static MapImage of(BufferedImage image) {
        int w = image.getWidth();
        int h = image.getHeight();
        double[] with = new double[w * h];
        double[] without = new double[w * h];
        ColorModel cm = image.getColorModel();
        boolean alpha = cm.hasAlpha();
        if (cm instanceof IndexColorModel) {
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    int argb = image.getRGB(x, y);
                    int sum = ((argb >> 16) & 0xff) + ((argb >> 8) & 0xff) + (argb & 0xff);
                    without[y * w + x] = sum / 3.0;
                    with[y * w + x] = alpha ? (sum + ((argb >>> 24) & 0xff)) / 4.0 : sum / 3.0;
                }
            }
            return new MapImage(w, h, with, without);
        }
        Raster raster = image.getRaster();
        int bands = raster.getNumBands();
        int colourBands = alpha ? bands - 1 : bands;
        double[] scale = new double[bands];
        for (int b = 0; b < bands; b++) {
            scale[b] = 255.0 / ((1L << cm.getComponentSize(b)) - 1);
        }
        int[] px = new int[bands];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                raster.getPixel(x, y, px);
                double colour = 0;
                for (int b = 0; b < colourBands; b++) {
                    colour += px[b] * scale[b];
                }
                without[y * w + x] = colour / colourBands;
                with[y * w + x] = alpha ? (colour + px[bands - 1] * scale[bands - 1]) / bands : colour / colourBands;
            }
        }
        return new MapImage(w, h, with, without);
    }
}
