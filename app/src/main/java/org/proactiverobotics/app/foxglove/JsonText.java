package org.proactiverobotics.app.foxglove;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * One JSON message at a time, written by hand into a reused buffer: numbers with a fixed number of
 * decimals (the same text on every machine, no Double.toString), strings escaped, and the result
 * as UTF-8 bytes in a reused array. About ten messages per iteration go through it, so it
 * allocates nothing for ASCII text.
 */
final class JsonText {

    private static final long[] SCALE = {1, 10, 100, 1000, 10_000, 100_000, 1_000_000};
    private final StringBuilder text = new StringBuilder(4096);
    private byte[] bytes = new byte[4096];
    private int length;
    /** Whether the next value needs a comma before it. */
    private boolean comma;

    JsonText begin() {
        text.setLength(0);
        comma = false;
        return this;
    }

    JsonText open() {
        sep();
        text.append('{');
        comma = false;
        return this;
    }

    JsonText close() {
        text.append('}');
        comma = true;
        return this;
    }

    JsonText openArray() {
        sep();
        text.append('[');
        comma = false;
        return this;
    }

    JsonText closeArray() {
        text.append(']');
        comma = true;
        return this;
    }

    /** A member's name; its value follows. */
    JsonText name(String name) {
        sep();
        text.append('"').append(name).append("\":");
        comma = false;
        return this;
    }

    /** @param decimals 0 to 6; the value rounded half up to them, trailing zeros dropped */
    JsonText number(double v, int decimals) {
        sep();
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException("JSON has no " + v);
        }
        long units = Math.round(v * SCALE[decimals]);
        if (units < 0) {
            text.append('-');
            units = -units;
        }
        long scale = SCALE[decimals];
        text.append(units / scale);
        long fraction = units % scale;
        if (fraction != 0) {
            int digits = decimals;
            while (fraction % 10 == 0) {
                fraction /= 10;
                digits--;
            }
            text.append('.');
            for (long f = fraction * 10; f < SCALE[digits]; f *= 10) {
                text.append('0');
            }
            text.append(fraction);
        }
        comma = true;
        return this;
    }

    JsonText integer(long v) {
        sep();
        text.append(v);
        comma = true;
        return this;
    }

    JsonText bool(boolean v) {
        sep();
        text.append(v);
        comma = true;
        return this;
    }

    JsonText nullValue() {
        sep();
        text.append("null");
        comma = true;
        return this;
    }

    JsonText string(String s) {
        sep();
        text.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> text.append("\\\"");
                case '\\' -> text.append("\\\\");
                case '\n' -> text.append("\\n");
                case '\r' -> text.append("\\r");
                case '\t' -> text.append("\\t");
                default -> {
                    if (c < 0x20) {
                        text.append(String.format("\\u%04x", (int) c));
                    } else {
                        text.append(c);
                    }
                }
            }
        }
        text.append('"');
        comma = true;
        return this;
    }

    /** Already-written JSON, as is. */
    JsonText raw(CharSequence json) {
        sep();
        text.append(json);
        comma = true;
        return this;
    }

    /** {"sec":..,"nsec":..} of a simulated time in ms. */
    JsonText time(long simTimeMs) {
        open();
        name("sec").integer(simTimeMs / 1000);
        name("nsec").integer(simTimeMs % 1000 * 1_000_000L);
        return close();
    }

    /** Ends the message: its UTF-8 bytes are {@link #bytes()}[0, {@link #length()}). */
    JsonText end() {
        int n = text.length();
        if (bytes.length < n) {
            bytes = new byte[Math.max(n, bytes.length * 2)];
        }
        for (int i = 0; i < n; i++) {
            char c = text.charAt(i);
            if (c >= 0x80) { // rare: a scenario or message with non-ASCII letters
                byte[] utf8 = text.toString().getBytes(StandardCharsets.UTF_8);
                if (bytes.length < utf8.length) {
                    bytes = Arrays.copyOf(bytes, utf8.length);
                }
                System.arraycopy(utf8, 0, bytes, 0, utf8.length);
                length = utf8.length;
                return this;
            }
            bytes[i] = (byte) c;
        }
        length = n;
        return this;
    }

    byte[] bytes() {
        return bytes;
    }

    int length() {
        return length;
    }

    @Override
    public String toString() {
        return text.toString();
    }

    private void sep() {
        if (comma) {
            text.append(',');
        }
    }
}
