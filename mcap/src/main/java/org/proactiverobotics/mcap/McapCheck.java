package org.proactiverobotics.mcap;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.zip.CRC32;

/**
 * Reads an MCAP file from end to end and says whether it is whole: the magic at both ends, every
 * record's length, the data section up to Data End (with its CRC32), every uncompressed chunk (its
 * CRC32, its messages and their channels), the summary (its CRC32, the Statistics against what the
 * data section holds, each Chunk Index against its chunk) and the Footer. A file cut short (a
 * writer killed before it closed) is {@link Report#incomplete() incomplete}, with the byte where it
 * ends and what could still be read; never an exception. Reads the whole file into memory.
 */
public final class McapCheck {

    /**
     * A channel and the messages found on it.
     *
     * @param id         its id
     * @param topic      its topic
     * @param schemaName its schema's name ("" without a schema)
     * @param messages   messages read on it
     */
    public record ChannelCount(int id, String topic, String schemaName, long messages) {
    }

    /**
     * What the check found.
     *
     * @param sizeBytes    the file's size
     * @param problem      null when the file is whole and consistent; else what is wrong, in words
     * @param incomplete   true when the file merely ends too early (cut short), false when whole or corrupt
     * @param cutAtByte    where a cut-short file ends (its size); -1 otherwise
     * @param channels     the channels read, by id, with their message counts
     * @param messages     the messages read
     * @param chunks       the chunks read
     * @param startTimeNs  the earliest message log time read (0: none)
     * @param endTimeNs    the latest message log time read (0: none)
     */
    public record Report(long sizeBytes, String problem, boolean incomplete, long cutAtByte, List<ChannelCount> channels,
                         long messages, int chunks, long startTimeNs, long endTimeNs) {

        /** @return true when the file is a whole, consistent MCAP file */
        public boolean ok() {
            return problem == null;
        }
    }

    private final byte[] b;
    private final Map<Integer, String> schemas = new TreeMap<>();
    private final Map<Integer, String[]> channels = new TreeMap<>();
    private final Map<Integer, Long> counts = new TreeMap<>();
    private final Map<Long, Long> chunkLengths = new LinkedHashMap<>();
    private long messages;
    private int chunks;
    private long start = -1;
    private long end;

    private McapCheck(byte[] bytes) {
        this.b = bytes;
    }

    /**
     * @param file an MCAP file
     * @return what it holds and what is wrong with it, if anything
     * @throws IOException when the file cannot be read at all
     */
    public static Report check(Path file) throws IOException {
        return check(Files.readAllBytes(file));
    }

    /**
     * @param bytes an MCAP file's bytes
     * @return what they hold and what is wrong with them, if anything
     */
    public static Report check(byte[] bytes) {
        McapCheck c = new McapCheck(bytes);
        String problem;
        boolean cut = false;
        try {
            problem = c.read();
        } catch (Cut e) {
            problem = e.getMessage();
            cut = true;
        } catch (Corrupt e) {
            problem = e.getMessage();
        }
        return c.report(problem, cut);
    }

    private Report report(String problem, boolean cut) {
        List<ChannelCount> list = new ArrayList<>();
        channels.forEach((id, c) -> list.add(new ChannelCount(id, c[0], c[1], counts.getOrDefault(id, 0L))));
        return new Report(b.length, problem, cut, cut ? b.length : -1, Collections.unmodifiableList(list), messages, chunks,
                start < 0 ? 0 : start, end);
    }

    /** @return null when whole, else the problem */
    private String read() {
        if (b.length < Opcode.MAGIC.length) {
            if (Arrays.equals(b, 0, b.length, Opcode.MAGIC, 0, b.length)) {
                throw new Cut("the file ends inside the leading magic");
            }
            throw new Corrupt("it does not start with the MCAP magic bytes");
        }
        if (!Arrays.equals(b, 0, 8, Opcode.MAGIC, 0, 8)) {
            throw new Corrupt("it does not start with the MCAP magic bytes");
        }
        CRC32 dataCrc = new CRC32();
        long pos = 8;
        boolean first = true;
        while (true) {
            int op = opcodeAt(pos, "the data section has no Data End record");
            long len = lengthAt(pos, op);
            long content = pos + Opcode.RECORD_PREFIX;
            if (first && op != Opcode.HEADER) {
                throw new Corrupt("the first record is a " + Opcode.name(op) + ", not a Header");
            }
            first = false;
            if (op == Opcode.DATA_END) {
                dataCrc.update(b, 0, (int) pos);
                long expected = u32(content);
                if (expected != 0 && expected != dataCrc.getValue()) {
                    throw new Corrupt("the data section's CRC32 does not match its bytes");
                }
                pos = content + len;
                break;
            }
            switch (op) {
                case Opcode.SCHEMA, Opcode.CHANNEL, Opcode.MESSAGE -> dataRecord(op, content, len);
                case Opcode.CHUNK -> chunk(pos, content, len);
                case Opcode.FOOTER -> throw new Corrupt("a Footer at byte " + pos + " before any Data End record");
                default -> { } // message indexes, attachments, metadata: nothing to count
            }
            pos = content + len;
        }
        return summary(pos);
    }

    private String summary(long summaryStart) {
        long pos = summaryStart;
        Map<Integer, Long> statsCounts = null;
        long statsMessages = -1;
        int statsChunks = -1;
        List<long[]> chunkIndexes = new ArrayList<>();
        while (true) {
            int op = opcodeAt(pos, "no Footer after the summary section");
            long len = lengthAt(pos, op);
            long content = pos + Opcode.RECORD_PREFIX;
            if (op == Opcode.FOOTER) {
                if (len < 20) {
                    throw new Corrupt("the Footer is " + len + " bytes long, not 20");
                }
                long after = content + len;
                if (after + 8 > b.length) {
                    throw new Cut("the file ends inside the trailing magic");
                }
                if (!Arrays.equals(b, (int) after, (int) after + 8, Opcode.MAGIC, 0, 8)) {
                    throw new Corrupt("the Footer is not followed by the MCAP magic");
                }
                if (after + 8 != b.length) {
                    throw new Corrupt((b.length - after - 8) + " bytes follow the trailing magic");
                }
                long footerSummaryStart = u64(content);
                long summaryCrc = u32(content + 16);
                if (footerSummaryStart != 0 && footerSummaryStart != summaryStart) {
                    throw new Corrupt("the Footer puts the summary at byte " + footerSummaryStart + ", it starts at byte "
                            + summaryStart);
                }
                if (summaryCrc != 0) {
                    CRC32 crc = new CRC32();
                    crc.update(b, (int) summaryStart, (int) (content + 16 - summaryStart));
                    if (crc.getValue() != summaryCrc) {
                        throw new Corrupt("the summary's CRC32 does not match its bytes");
                    }
                }
                break;
            }
            switch (op) {
                case Opcode.STATISTICS -> {
                    statsMessages = u64(content);
                    statsChunks = (int) u32(content + 2 + 8 + 4 + 4 + 4);
                    long mapAt = content + 8 + 2 + 4 + 4 + 4 + 4 + 8 + 8;
                    long mapEnd = mapAt + 4 + u32(mapAt);
                    statsCounts = new TreeMap<>();
                    for (long p = mapAt + 4; p < mapEnd; p += 10) {
                        statsCounts.put(u16(p), u64(p + 2));
                    }
                }
                case Opcode.CHUNK_INDEX -> chunkIndexes.add(new long[] {u64(content + 16), u64(content + 24)});
                default -> { }
            }
            pos = content + len;
        }
        if (statsCounts != null) {
            if (statsMessages != messages || statsChunks != chunks) {
                throw new Corrupt("the Statistics count " + statsMessages + " messages in " + statsChunks
                        + " chunks; the data section holds " + messages + " in " + chunks);
            }
            Map<Integer, Long> nonZero = new TreeMap<>(counts);
            nonZero.values().removeIf(v -> v == 0);
            if (!statsCounts.isEmpty() && !statsCounts.equals(nonZero)) {
                throw new Corrupt("the Statistics' message counts by channel " + statsCounts
                        + " differ from the data section's " + nonZero);
            }
        }
        if (!chunkIndexes.isEmpty() && chunkIndexes.size() != chunks) {
            throw new Corrupt(chunkIndexes.size() + " Chunk Index records for " + chunks + " chunks");
        }
        for (long[] ci : chunkIndexes) {
            Long length = chunkLengths.get(ci[0]);
            if (length == null || length != ci[1]) {
                throw new Corrupt("a Chunk Index points at byte " + ci[0] + ", where no chunk of " + ci[1] + " bytes starts");
            }
        }
        return null;
    }

    private void chunk(long recordStart, long content, long len) {
        long uncompressedSize = u64(content + 16);
        long uncompressedCrc = u32(content + 24);
        String compression = string(content + 28);
        long recordsAt = content + 28 + 4 + compression.getBytes(StandardCharsets.UTF_8).length;
        long recordsLength = u64(recordsAt);
        long recordsStart = recordsAt + 8;
        if (recordsStart + recordsLength > content + len) {
            throw new Corrupt("the chunk at byte " + recordStart + " claims more records than it holds");
        }
        chunks++;
        chunkLengths.put(recordStart, Opcode.RECORD_PREFIX + len);
        if (!compression.isEmpty()) {
            return; // its messages cannot be counted without the codec
        }
        if (uncompressedSize != recordsLength) {
            throw new Corrupt("the chunk at byte " + recordStart + " says " + uncompressedSize + " bytes, holds " + recordsLength);
        }
        if (uncompressedCrc != 0) {
            CRC32 crc = new CRC32();
            crc.update(b, (int) recordsStart, (int) recordsLength);
            if (crc.getValue() != uncompressedCrc) {
                throw new Corrupt("the chunk at byte " + recordStart + ": its CRC32 does not match its records");
            }
        }
        long p = recordsStart;
        long stop = recordsStart + recordsLength;
        while (p < stop) {
            if (p + Opcode.RECORD_PREFIX > stop) {
                throw new Corrupt("the chunk at byte " + recordStart + " ends inside a record");
            }
            int op = b[(int) p] & 0xFF;
            long l = u64(p + 1);
            if (l > stop - p - Opcode.RECORD_PREFIX) {
                throw new Corrupt("the chunk at byte " + recordStart + " ends inside a " + Opcode.name(op) + " record");
            }
            dataRecord(op, p + Opcode.RECORD_PREFIX, l);
            p += Opcode.RECORD_PREFIX + l;
        }
    }

    private void dataRecord(int op, long content, long len) {
        switch (op) {
            case Opcode.SCHEMA -> schemas.put(u16(content), string(content + 2));
            case Opcode.CHANNEL -> {
                int id = u16(content);
                int schemaId = u16(content + 2);
                if (schemaId != 0 && !schemas.containsKey(schemaId)) {
                    throw new Corrupt("channel " + id + " names schema " + schemaId + " before any Schema record of it");
                }
                channels.put(id, new String[] {string(content + 4), schemaId == 0 ? "" : schemas.get(schemaId)});
            }
            case Opcode.MESSAGE -> {
                int id = u16(content);
                if (!channels.containsKey(id)) {
                    throw new Corrupt("a message on channel " + id + " before any Channel record of it");
                }
                long t = u64(content + 6);
                counts.merge(id, 1L, Long::sum);
                messages++;
                if (start < 0 || Long.compareUnsigned(t, start) < 0) {
                    start = t;
                }
                if (Long.compareUnsigned(t, end) > 0) {
                    end = t;
                }
            }
            default -> { }
        }
    }

    private int opcodeAt(long pos, String whatIsMissing) {
        if (pos >= b.length) {
            throw new Cut("the file ends at a record boundary, but " + whatIsMissing);
        }
        if (pos + Opcode.RECORD_PREFIX > b.length) {
            throw new Cut("the file ends inside the length of a " + Opcode.name(b[(int) pos] & 0xFF) + " record at byte " + pos);
        }
        int op = b[(int) pos] & 0xFF;
        if (op == 0) {
            throw new Corrupt("a record with opcode 0 at byte " + pos);
        }
        return op;
    }

    private long lengthAt(long pos, int op) {
        long len = u64(pos + 1);
        long content = pos + Opcode.RECORD_PREFIX;
        if (len < 0 || len > b.length - content) {
            throw new Cut("the file ends inside a " + Opcode.name(op) + " record of " + (Opcode.RECORD_PREFIX + len)
                    + " bytes that starts at byte " + pos);
        }
        return len;
    }

    private int u16(long at) {
        need(at, 2);
        return (b[(int) at] & 0xFF) | (b[(int) at + 1] & 0xFF) << 8;
    }

    private long u32(long at) {
        need(at, 4);
        long v = 0;
        for (int i = 3; i >= 0; i--) {
            v = v << 8 | (b[(int) at + i] & 0xFF);
        }
        return v;
    }

    private long u64(long at) {
        need(at, 8);
        long v = 0;
        for (int i = 7; i >= 0; i--) {
            v = v << 8 | (b[(int) at + i] & 0xFF);
        }
        return v;
    }

    private String string(long at) {
        long n = u32(at);
        need(at + 4, n);
        return new String(b, (int) at + 4, (int) n, StandardCharsets.UTF_8);
    }

    private void need(long at, long n) {
        if (at < 0 || n < 0 || at + n > b.length) {
            throw new Corrupt("a field at byte " + at + " runs past the end of its record");
        }
    }

    /** The file ends too early. */
    private static final class Cut extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Cut(String message) {
            super(message, null, false, false);
        }
    }

    /** The bytes are not what the specification says. */
    private static final class Corrupt extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Corrupt(String message) {
            super(message, null, false, false);
        }
    }
}
