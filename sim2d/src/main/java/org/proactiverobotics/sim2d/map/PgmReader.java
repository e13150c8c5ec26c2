package org.proactiverobotics.sim2d.map;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Reads a PGM picture, plain (P2, numbers in text) or raw (P5, one or two bytes a pixel), into a
 * {@link MapImage}: the header's width, height and maxval, comments ({@code #} to the line's end) allowed
 * between them; every pixel scaled from 0–maxval to 0–255. A file whose pixels are fewer or more than its
 * header announces is refused, as is a value above maxval.
 */
final class PgmReader {

    private final Path file;
    private final byte[] bytes;
    private int pos;

    private PgmReader(Path file, byte[] bytes) {
        this.file = file;
        this.bytes = bytes;
    }

    /**
     * @param file a PGM file
     * @return its pixels
     * @throws MapException when it cannot be read or is not a consistent PGM
     */
    static MapImage read(Path file) {
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(file);
        } catch (IOException e) {
            throw new MapException(file, "cannot read the image: " + e.getMessage());
        }
        return new PgmReader(file, bytes).image();
    }

    private MapImage image() {
        if (bytes.length < 2 || bytes[0] != 'P' || (bytes[1] != '2' && bytes[1] != '5')) {
            throw problem("wrong magic number: not a PGM (P2 or P5)");
        }
        boolean plain = bytes[1] == '2';
        pos = 2;
        long width = headerNumber("width");
        long height = headerNumber("height");
        long maxval = headerNumber("maxval");
        if (width < 1 || height < 1) {
            throw problem("the header gives a size of " + width + " x " + height + " pixels");
        }
        if (width * height > MapImage.MAX_PIXELS) {
            throw problem("the header gives " + width + " x " + height + " pixels, more than the "
                    + MapImage.MAX_PIXELS + " a map may have");
        }
        if (maxval < 1 || maxval > 65535) {
            throw problem("maxval must be from 1 to 65535, the header gives " + maxval);
        }
        int w = (int) width;
        int h = (int) height;
        double[] means = new double[w * h];
        double scale = 255.0 / maxval;
        if (plain) {
            for (int k = 0; k < means.length; k++) {
                long v = pixelNumber(k, w, h);
                if (v > maxval) {
                    throw problem("pixel " + k + " is " + v + ", above the header's maxval " + maxval);
                }
                means[k] = v * scale;
            }
            skipSpaceAndComments();
            if (pos < bytes.length) {
                throw problem("more pixels than the header's " + w + " x " + h);
            }
        } else {
            // exactly one whitespace byte ends the header of a raw PGM
            if (pos >= bytes.length || !Character.isWhitespace(bytes[pos])) {
                throw problem("the header's maxval is not followed by a whitespace byte");
            }
            pos++;
            int bytesPerPixel = maxval < 256 ? 1 : 2;
            long expected = (long) w * h * bytesPerPixel;
            long actual = bytes.length - pos;
            if (actual != expected) {
                throw problem(String.format("the header says %d x %d pixels (%d bytes) but the file holds %d bytes of pixels",
                        w, h, expected, actual));
            }
            for (int k = 0; k < means.length; k++) {
                int v = bytesPerPixel == 1 ? bytes[pos + k] & 0xff
                        : ((bytes[pos + 2 * k] & 0xff) << 8) | (bytes[pos + 2 * k + 1] & 0xff);
                if (v > maxval) {
                    throw problem("pixel " + k + " is " + v + ", above the header's maxval " + maxval);
                }
                means[k] = v * scale;
            }
        }
        return new MapImage(w, h, means, means);
    }

    private long headerNumber(String what) {
        skipSpaceAndComments();
        long v = digits();
        if (v < 0) {
            throw problem("the header has no " + what);
        }
        return v;
    }

    private long pixelNumber(int k, int w, int h) {
        skipSpaceAndComments();
        long v = digits();
        if (v < 0) {
            throw problem(pos >= bytes.length
                    ? "the header says " + w + " x " + h + " pixels but the file holds only " + k
                    : "pixel " + k + " is not a number");
        }
        return v;
    }

    /** @return the decimal number at the position, or -1 when there is none */
    private long digits() {
        int start = pos;
        long v = 0;
        while (pos < bytes.length && bytes[pos] >= '0' && bytes[pos] <= '9') {
            v = Math.min(v * 10 + (bytes[pos] - '0'), Integer.MAX_VALUE); // a silly size saturates, then is refused
            pos++;
        }
        if (pos == start || (pos < bytes.length && !Character.isWhitespace(bytes[pos]) && bytes[pos] != '#')) {
            return -1;
        }
        return v;
    }

    private void skipSpaceAndComments() {
        while (pos < bytes.length) {
            if (bytes[pos] == '#') {
                while (pos < bytes.length && bytes[pos] != '\n' && bytes[pos] != '\r') {
                    pos++;
                }
            } else if (Character.isWhitespace(bytes[pos])) {
                pos++;
            } else {
                return;
            }
        }
    }

    private MapException problem(String what) {
        return new MapException(file, what);
    }
}
