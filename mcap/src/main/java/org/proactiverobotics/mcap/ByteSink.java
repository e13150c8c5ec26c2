package org.proactiverobotics.mcap;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * A growable byte array written little-endian, as every MCAP integer is; reused from record to
 * record (and chunk to chunk) so that writing a message allocates nothing.
 */
final class ByteSink {

    private byte[] bytes;
    private int size;

    ByteSink(int initialCapacity) {
        bytes = new byte[Math.max(16, initialCapacity)];
    }

    int size() {
        return size;
    }

    byte[] array() {
        return bytes;
    }

    void clear() {
        size = 0;
    }

    ByteSink u8(int v) {
        ensure(1);
        bytes[size++] = (byte) v;
        return this;
    }

    ByteSink u16(int v) {
        ensure(2);
        bytes[size++] = (byte) v;
        bytes[size++] = (byte) (v >>> 8);
        return this;
    }

    ByteSink u32(long v) {
        ensure(4);
        for (int i = 0; i < 4; i++) {
            bytes[size++] = (byte) (v >>> (8 * i));
        }
        return this;
    }

    ByteSink u64(long v) {
        ensure(8);
        for (int i = 0; i < 8; i++) {
            bytes[size++] = (byte) (v >>> (8 * i));
        }
        return this;
    }

    /** A String: uint32 byte length, then UTF-8. */
    ByteSink string(String s) {
        byte[] utf8 = s.getBytes(StandardCharsets.UTF_8);
        u32(utf8.length);
        return bytes(utf8, 0, utf8.length);
    }

    ByteSink bytes(byte[] b, int off, int len) {
        ensure(len);
        System.arraycopy(b, off, bytes, size, len);
        size += len;
        return this;
    }

    /** Overwrites a uint32 written earlier (a length known only afterwards). */
    void u32At(int at, long v) {
        for (int i = 0; i < 4; i++) {
            bytes[at + i] = (byte) (v >>> (8 * i));
        }
    }

    /** Overwrites a uint64 written earlier. */
    void u64At(int at, long v) {
        for (int i = 0; i < 8; i++) {
            bytes[at + i] = (byte) (v >>> (8 * i));
        }
    }

    /** Starts a record: opcode and a length to be filled by {@link #endRecord}; returns where the length is. */
    int beginRecord(int opcode) {
        u8(opcode);
        int at = size;
        u64(0);
        return at;
    }

    void endRecord(int lengthAt) {
        u64At(lengthAt, size - lengthAt - 8);
    }

    private void ensure(int more) {
        if (size + more > bytes.length) {
            bytes = Arrays.copyOf(bytes, Math.max(bytes.length * 2, size + more));
        }
    }
}
