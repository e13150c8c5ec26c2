package org.proactiverobotics.sim2d.map;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import javax.imageio.ImageIO;

/** Maps the tests make themselves: PGM (P2, P5), PNG and map_server YAML files. */
final class MapFixtures {

    private MapFixtures() {
    }

    /** Writes a raw PGM; values row by row from the top, 1 byte a pixel (2 when maxval > 255). */
    static Path p5(Path file, int w, int h, int maxval, int... values) throws IOException {
        byte[] header = String.format(Locale.ROOT, "P5\n# made by a test\n%d %d\n%d\n", w, h, maxval)
                .getBytes(StandardCharsets.US_ASCII);
        int bpp = maxval > 255 ? 2 : 1;
        byte[] bytes = new byte[header.length + values.length * bpp];
        System.arraycopy(header, 0, bytes, 0, header.length);
        for (int k = 0; k < values.length; k++) {
            if (bpp == 1) {
                bytes[header.length + k] = (byte) values[k];
            } else {
                bytes[header.length + 2 * k] = (byte) (values[k] >> 8);
                bytes[header.length + 2 * k + 1] = (byte) values[k];
            }
        }
        Files.write(file, bytes);
        return file;
    }

    /** Writes a plain PGM, a comment in the header and the values a row a line. */
    static Path p2(Path file, int w, int h, int maxval, int... values) throws IOException {
        StringBuilder sb = new StringBuilder(String.format(Locale.ROOT, "P2\n%d %d # width height\n%d\n", w, h, maxval));
        for (int k = 0; k < values.length; k++) {
            sb.append(values[k]).append(k % w == w - 1 ? "\n" : " ");
        }
        Files.writeString(file, sb.toString(), StandardCharsets.US_ASCII);
        return file;
    }

    /** Writes an 8-bit grey PNG. */
    static Path greyPng(Path file, int w, int h, int... values) throws IOException {
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_BYTE_GRAY);
        for (int k = 0; k < values.length; k++) {
            image.getRaster().setSample(k % w, k / w, 0, values[k]);
        }
        ImageIO.write(image, "png", file.toFile());
        return file;
    }

    /** Writes an RGBA PNG; each pixel given as 0xAARRGGBB. */
    static Path argbPng(Path file, int w, int h, int... argb) throws IOException {
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_ARGB);
        for (int k = 0; k < argb.length; k++) {
            image.setRGB(k % w, k / w, argb[k]);
        }
        ImageIO.write(image, "png", file.toFile());
        return file;
    }

    /** Writes a YAML of the given lines. */
    static Path yaml(Path file, String... lines) throws IOException {
        Files.writeString(file, String.join("\n", lines) + "\n", StandardCharsets.UTF_8);
        return file;
    }

    /** @return the grid's cells as text, the top row first: '#' blocked, '.' free */
    static String picture(OccupancyGrid g) {
        StringBuilder sb = new StringBuilder();
        for (int j = g.rows() - 1; j >= 0; j--) {
            for (int i = 0; i < g.columns(); i++) {
                sb.append(g.blocked(i, j) ? '#' : '.');
            }
            sb.append('\n');
        }
        return sb.toString();
    }
}
