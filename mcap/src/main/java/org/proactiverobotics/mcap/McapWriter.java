package org.proactiverobotics.mcap;

import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.zip.CRC32;

/**
 * Writes an indexed MCAP file as a stream: the leading magic and Header at once, then Schema,
 * Channel and Message records gathered into uncompressed Chunks of about {@code chunkSizeBytes},
 * each chunk followed by one Message Index per channel it holds; {@link #close()} adds Data End
 * (with the data section's CRC32), the summary section (Schema, Channel, Statistics and Chunk
 * Index records, grouped by opcode), a Summary Offset per group, the Footer (with the summary's
 * CRC32) and the trailing magic. A file cut short (the process killed) keeps every chunk written
 * so far; {@link McapCheck} reports it as incomplete.
 * <p>
 * The bytes depend only on what the caller gives: no clock is read. Times are uint64 nanoseconds
 * in the caller's epoch. Log times should not decrease (the indexes assume so for seeking). Not
 * thread-safe.
 */
public final class McapWriter implements AutoCloseable {

    /** The chunk size used when none is given: 256 KiB of records, a seek step of well under a second of a run. */
    public static final int DEFAULT_CHUNK_SIZE_BYTES = 256 * 1024;

    private final OutputStream out;
    private final int chunkSizeBytes;
    private final CRC32 crc = new CRC32();
    private final CRC32 chunkCrc = new CRC32();
    private final ByteSink record = new ByteSink(256);
    private final ByteSink chunk;
    private final List<byte[]> schemaRecords = new ArrayList<>();
    private final List<byte[]> channelRecords = new ArrayList<>();
    private final ByteSink chunkIndexes = new ByteSink(1024);
    private long position;
    private boolean closed;

    // per channel (index = channel id): sequence, message count, this chunk's index entries
    private int[] sequence = new int[8];
    private long[] messageCounts = new long[8];
    private long[][] indexEntries = new long[8][];
    private int[] indexSizes = new int[8];
    private int channelCount;
    private int schemaCount;
    private long messageCount;
    private long firstLogTime = -1;
    private long lastLogTime;
    private long chunkStart = -1;
    private long chunkEnd;
    private int chunkCount;

    /**
     * Writes the leading magic and the Header.
     *
     * @param out            where the file goes (buffered by the caller; closed by {@link #close()})
     * @param profile        the Header's profile ("" when none of the well-known ones applies)
     * @param library        the Header's library: the writer's name and version, fixed for equal bytes
     * @param chunkSizeBytes records gathered before a chunk is written (a chunk may be one message larger)
     * @throws IOException when the stream fails
     */
    public McapWriter(OutputStream out, String profile, String library, int chunkSizeBytes) throws IOException {
        this.out = Objects.requireNonNull(out, "out");
        if (chunkSizeBytes < 1) {
            throw new IllegalArgumentException("chunk size must be at least 1 byte: " + chunkSizeBytes);
        }
        this.chunkSizeBytes = chunkSizeBytes;
        this.chunk = new ByteSink(Math.min(chunkSizeBytes, 1 << 20) + 4096);
        emit(Opcode.MAGIC, 0, Opcode.MAGIC.length);
        record.clear();
        int at = record.beginRecord(Opcode.HEADER);
        record.string(profile).string(library);
        record.endRecord(at);
        emit(record.array(), 0, record.size());
    }

    /**
     * Adds a schema; its record goes into the data section now and into the summary at the end.
     *
     * @param name     e.g. {@code foxglove.LaserScan}
     * @param encoding e.g. {@code jsonschema}
     * @param data     the schema itself
     * @return the schema's id (from 1)
     */
    public int schema(String name, String encoding, byte[] data) {
        checkOpen();
        if (schemaCount == 0xFFFF) {
            throw new IllegalStateException("an MCAP file holds at most 65535 schemas");
        }
        int id = ++schemaCount;
        record.clear();
        int at = record.beginRecord(Opcode.SCHEMA);
        record.u16(id).string(name).string(encoding).u32(data.length).bytes(data, 0, data.length);
        record.endRecord(at);
        schemaRecords.add(Arrays.copyOf(record.array(), record.size()));
        chunk.bytes(record.array(), 0, record.size());
        return id;
    }

    /**
     * Adds a channel; its record goes into the data section now and into the summary at the end.
     *
     * @param topic           e.g. {@code /scan}
     * @param schemaId        from {@link #schema}, or 0 for none
     * @param messageEncoding e.g. {@code json}
     * @param metadata        written in the map's iteration order (give a sorted or ordered map for equal bytes)
     * @return the channel's id (from 0)
     */
    public int channel(String topic, int schemaId, String messageEncoding, Map<String, String> metadata) {
        checkOpen();
        if (schemaId < 0 || schemaId > schemaCount) {
            throw new IllegalArgumentException("no schema " + schemaId + " for channel " + topic);
        }
        if (channelCount == 0xFFFF) {
            throw new IllegalStateException("an MCAP file holds at most 65535 channels");
        }
        int id = channelCount++;
        growChannels(channelCount);
        record.clear();
        int at = record.beginRecord(Opcode.CHANNEL);
        record.u16(id).u16(schemaId).string(topic).string(messageEncoding);
        int mapAt = record.size();
        record.u32(0);
        for (Map.Entry<String, String> e : metadata.entrySet()) {
            record.string(e.getKey()).string(e.getValue());
        }
        record.u32At(mapAt, record.size() - mapAt - 4);
        record.endRecord(at);
        channelRecords.add(Arrays.copyOf(record.array(), record.size()));
        chunk.bytes(record.array(), 0, record.size());
        return id;
    }

    /**
     * Adds a message to the open chunk (publish time = log time), writing the chunk when it is full.
     *
     * @param channelId  from {@link #channel}
     * @param logTimeNs  when it was recorded, ns
     * @param data       the message's bytes, in the channel's encoding
     * @param offset     where they start in {@code data}
     * @param length     how many
     * @throws IOException when the stream fails
     */
    public void message(int channelId, long logTimeNs, byte[] data, int offset, int length) throws IOException {
        checkOpen();
        if (channelId < 0 || channelId >= channelCount) {
            throw new IllegalArgumentException("no channel " + channelId);
        }
        long recordOffset = chunk.size();
        int at = chunk.beginRecord(Opcode.MESSAGE);
        chunk.u16(channelId).u32(sequence[channelId]++ & 0xFFFFFFFFL).u64(logTimeNs).u64(logTimeNs)
                .bytes(data, offset, length);
        chunk.endRecord(at);
        index(channelId, logTimeNs, recordOffset);
        messageCounts[channelId]++;
        messageCount++;
        if (firstLogTime < 0 || Long.compareUnsigned(logTimeNs, firstLogTime) < 0) {
            firstLogTime = logTimeNs;
        }
        if (Long.compareUnsigned(logTimeNs, lastLogTime) > 0) {
            lastLogTime = logTimeNs;
        }
        if (chunkStart < 0 || Long.compareUnsigned(logTimeNs, chunkStart) < 0) {
            chunkStart = logTimeNs;
        }
        if (Long.compareUnsigned(logTimeNs, chunkEnd) > 0) {
            chunkEnd = logTimeNs;
        }
        if (chunk.size() >= chunkSizeBytes) {
            writeChunk();
        }
    }

    /** @return messages added so far */
    public long messageCount() {
        return messageCount;
    }

    /** @return bytes written to the stream so far (the open chunk not included) */
    public long bytesWritten() {
        return position;
    }

    /**
     * Writes the open chunk, Data End, the summary section, the Summary Offsets, the Footer and the
     * trailing magic, then closes the stream. Closing twice does nothing.
     *
     * @throws IOException when the stream fails
     */
    @Override
    public void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        try {
            if (chunk.size() > 0) {
                writeChunk();
            }
            record.clear();
            int at = record.beginRecord(Opcode.DATA_END);
            record.u32(crc.getValue());
            record.endRecord(at);
            emit(record.array(), 0, record.size());

            crc.reset(); // from here on: the summary's CRC
            long summaryStart = position;
            ByteSink offsets = new ByteSink(128);
            group(offsets, Opcode.SCHEMA, schemaRecords);
            group(offsets, Opcode.CHANNEL, channelRecords);
            long statisticsStart = position;
            emitStatistics();
            summaryOffset(offsets, Opcode.STATISTICS, statisticsStart, position - statisticsStart);
            if (chunkIndexes.size() > 0) {
                long start = position;
                emit(chunkIndexes.array(), 0, chunkIndexes.size());
                summaryOffset(offsets, Opcode.CHUNK_INDEX, start, position - start);
            }
            long summaryOffsetStart = position;
            emit(offsets.array(), 0, offsets.size());

            record.clear();
            record.u8(Opcode.FOOTER).u64(8 + 8 + 4).u64(summaryStart).u64(summaryOffsetStart);
            emit(record.array(), 0, record.size());
            record.clear();
            record.u32(crc.getValue());
            emit(record.array(), 0, record.size());
            emit(Opcode.MAGIC, 0, Opcode.MAGIC.length);
        } finally {
            out.close();
        }
    }

    private void group(ByteSink offsets, int opcode, List<byte[]> records) throws IOException {
        if (records.isEmpty()) {
            return;
        }
        long start = position;
        for (byte[] r : records) {
            emit(r, 0, r.length);
        }
        summaryOffset(offsets, opcode, start, position - start);
    }

    private static void summaryOffset(ByteSink offsets, int opcode, long start, long length) {
        int at = offsets.beginRecord(Opcode.SUMMARY_OFFSET);
        offsets.u8(opcode).u64(start).u64(length);
        offsets.endRecord(at);
    }

    private void emitStatistics() throws IOException {
        record.clear();
        int at = record.beginRecord(Opcode.STATISTICS);
        record.u64(messageCount).u16(schemaCount).u32(channelCount).u32(0).u32(0).u32(chunkCount)
                .u64(messageCount == 0 ? 0 : firstLogTime).u64(messageCount == 0 ? 0 : lastLogTime);
        int mapAt = record.size();
        record.u32(0);
        for (int c = 0; c < channelCount; c++) {
            if (messageCounts[c] > 0) {
                record.u16(c).u64(messageCounts[c]);
            }
        }
        record.u32At(mapAt, record.size() - mapAt - 4);
        record.endRecord(at);
        emit(record.array(), 0, record.size());
    }

    /** The open chunk as a Chunk record, its Message Indexes after it, its Chunk Index kept for the summary. */
    private void writeChunk() throws IOException {
        chunkCrc.reset();
        chunkCrc.update(chunk.array(), 0, chunk.size());
        long start = chunkStart < 0 ? 0 : chunkStart;
        long end = chunkStart < 0 ? 0 : chunkEnd;
        long chunkOffset = position;
        record.clear();
        record.u8(Opcode.CHUNK);
        String compression = "";
        long contentLength = 8 + 8 + 8 + 4 + 4 + compression.length() + 8 + (long) chunk.size();
        record.u64(contentLength).u64(start).u64(end).u64(chunk.size()).u32(chunkCrc.getValue()).string(compression)
                .u64(chunk.size());
        emit(record.array(), 0, record.size());
        emit(chunk.array(), 0, chunk.size());
        long chunkLength = position - chunkOffset;

        long indexesStart = position;
        int ciAt = chunkIndexes.beginRecord(Opcode.CHUNK_INDEX);
        chunkIndexes.u64(start).u64(end).u64(chunkOffset).u64(chunkLength);
        int mapAt = chunkIndexes.size();
        chunkIndexes.u32(0);
        for (int c = 0; c < channelCount; c++) {
            int n = indexSizes[c];
            if (n == 0) {
                continue;
            }
            chunkIndexes.u16(c).u64(position);
            record.clear();
            int at = record.beginRecord(Opcode.MESSAGE_INDEX);
            record.u16(c).u32(n * 8L);
            long[] entries = indexEntries[c];
            for (int i = 0; i < n; i++) {
                record.u64(entries[i]);
            }
            record.endRecord(at);
            emit(record.array(), 0, record.size());
            indexSizes[c] = 0;
        }
        chunkIndexes.u32At(mapAt, chunkIndexes.size() - mapAt - 4);
        chunkIndexes.u64(position - indexesStart).string(compression).u64(chunk.size()).u64(chunk.size());
        chunkIndexes.endRecord(ciAt);

        chunkCount++;
        chunk.clear();
        chunkStart = -1;
        chunkEnd = 0;
    }

    private void index(int channelId, long logTimeNs, long offset) {
        long[] entries = indexEntries[channelId];
        int n = indexSizes[channelId];
        if (entries == null || n + 2 > entries.length) {
            entries = entries == null ? new long[64] : Arrays.copyOf(entries, entries.length * 2);
            indexEntries[channelId] = entries;
        }
        entries[n] = logTimeNs;
        entries[n + 1] = offset;
        indexSizes[channelId] = n + 2;
    }

    private void growChannels(int n) {
        if (n > sequence.length) {
            int size = Math.max(n, sequence.length * 2);
            sequence = Arrays.copyOf(sequence, size);
            messageCounts = Arrays.copyOf(messageCounts, size);
            indexEntries = Arrays.copyOf(indexEntries, size);
            indexSizes = Arrays.copyOf(indexSizes, size);
        }
    }

    private void emit(byte[] b, int off, int len) throws IOException {
        out.write(b, off, len);
        crc.update(b, off, len);
        position += len;
    }

    private void checkOpen() {
        if (closed) {
            throw new IllegalStateException("the MCAP writer is closed");
        }
    }
}
