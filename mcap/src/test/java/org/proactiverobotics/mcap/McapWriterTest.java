package org.proactiverobotics.mcap;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Map;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;

class McapWriterTest {

    /** Two channels, 500 messages over several small chunks. */
    private static byte[] sample(int chunkSize) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (McapWriter w = new McapWriter(bytes, "", "test", chunkSize)) {
            int schema = w.schema("example.Point", "jsonschema", "{\"type\":\"object\"}".getBytes(StandardCharsets.UTF_8));
            int a = w.channel("/a", schema, "json", Map.of());
            int b = w.channel("/b", 0, "json", new TreeMap<>(Map.of("k", "v")));
            for (int i = 0; i < 500; i++) {
                byte[] data = ("{\"i\":" + i + "}").getBytes(StandardCharsets.UTF_8);
                w.message(i % 3 == 0 ? b : a, i * 1_000_000L, data, 0, data.length);
            }
        }
        return bytes.toByteArray();
    }

    @Test
    void aClosedFileIsWholeWithEveryMessageCountedByChannel() throws IOException {
        McapCheck.Report r = McapCheck.check(sample(1024));

        assertThat(r.problem()).isNull();
        assertThat(r.ok()).isTrue();
        assertThat(r.messages()).isEqualTo(500);
        assertThat(r.chunks()).isGreaterThan(5);
        assertThat(r.channels()).containsExactly(new McapCheck.ChannelCount(0, "/a", "example.Point", 333),
                new McapCheck.ChannelCount(1, "/b", "", 167));
        assertThat(r.startTimeNs()).isZero();
        assertThat(r.endTimeNs()).isEqualTo(499_000_000L);
    }

    @Test
    void theFileStartsAndEndsWithTheMagicAndTheFooterPointsAtTheSummary() throws IOException {
        byte[] f = sample(1024);
        byte[] magic = {(byte) 0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};

        assertThat(Arrays.copyOfRange(f, 0, 8)).isEqualTo(magic);
        assertThat(Arrays.copyOfRange(f, f.length - 8, f.length)).isEqualTo(magic);
        int footer = f.length - 8 - 29;
        assertThat(f[footer]).isEqualTo((byte) 0x02);
        long summaryStart = le(f, footer + 9, 8);
        long summaryOffsetStart = le(f, footer + 17, 8);
        assertThat(f[(int) summaryStart]).as("the summary opens with the Schema group").isEqualTo((byte) 0x03);
        assertThat(f[(int) summaryOffsetStart]).isEqualTo((byte) 0x0E);
        assertThat(f[(int) summaryStart - 13]).as("Data End just before the summary").isEqualTo((byte) 0x0F);
    }

    @Test
    void theSameInputGivesTheSameBytes() throws IOException {
        assertThat(sample(4096)).isEqualTo(sample(4096));
    }

    @Test
    void aFileCutAnywhereIsIncompleteNeverWholeNorACrash() throws IOException {
        byte[] f = sample(2048);
        // every byte of the head and the tail (header, first chunk, summary, footer), every 7th in between
        for (int cut = 0; cut < f.length; cut += cut < 3000 || cut > f.length - 3000 ? 1 : 7) {
            McapCheck.Report r = McapCheck.check(Arrays.copyOf(f, cut));
            assertThat(r.ok()).as("cut at %d", cut).isFalse();
            assertThat(r.incomplete()).as("cut at %d: %s", cut, r.problem()).isTrue();
            assertThat(r.cutAtByte()).isEqualTo(cut);
        }
    }

    @Test
    void aCutFileStillCountsTheMessagesOfItsWholeChunks() throws IOException {
        byte[] f = sample(2048);
        McapCheck.Report r = McapCheck.check(Arrays.copyOf(f, f.length / 2));

        assertThat(r.messages()).isBetween(100L, 400L);
        assertThat(r.problem()).startsWith("the file ends inside a ");
    }

    @Test
    void aChangedByteInAChunkIsCaughtByItsCrc() throws IOException {
        byte[] f = sample(1 << 20);
        int at = indexOf(f, "{\"i\":250}".getBytes(StandardCharsets.UTF_8));
        f[at + 5] = '9';

        McapCheck.Report r = McapCheck.check(f);

        assertThat(r.incomplete()).isFalse();
        assertThat(r.problem()).contains("CRC32 does not match");
    }

    @Test
    void notAnMcapFileIsSaidSo() {
        McapCheck.Report r = McapCheck.check("{\"iteration\": 1}\n".getBytes(StandardCharsets.UTF_8));

        assertThat(r.incomplete()).isFalse();
        assertThat(r.problem()).isEqualTo("it does not start with the MCAP magic bytes");
    }

    private static long le(byte[] b, int at, int n) {
        long v = 0;
        for (int i = n - 1; i >= 0; i--) {
            v = v << 8 | (b[at + i] & 0xFF);
        }
        return v;
    }

    private static int indexOf(byte[] hay, byte[] needle) {
        outer:
        for (int i = 0; i + needle.length <= hay.length; i++) {
            for (int j = 0; j < needle.length; j++) {
                if (hay[i + j] != needle[j]) {
                    continue outer;
                }
            }
            return i;
        }
        throw new AssertionError("not found");
    }
}
