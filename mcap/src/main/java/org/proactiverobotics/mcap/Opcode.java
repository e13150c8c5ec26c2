package org.proactiverobotics.mcap;

/** The record opcodes of the MCAP specification that this package writes or reads. */
final class Opcode {

    static final int HEADER = 0x01;
    static final int FOOTER = 0x02;
    static final int SCHEMA = 0x03;
    static final int CHANNEL = 0x04;
    static final int MESSAGE = 0x05;
    static final int CHUNK = 0x06;
    static final int MESSAGE_INDEX = 0x07;
    static final int CHUNK_INDEX = 0x08;
    static final int STATISTICS = 0x0B;
    static final int SUMMARY_OFFSET = 0x0E;
    static final int DATA_END = 0x0F;

    /** The 8 bytes at both ends of a file: 0x89 "MCAP" major version '0' "\r\n". */
    static final byte[] MAGIC = {(byte) 0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};

    /** Opcode byte plus the uint64 content length. */
    static final int RECORD_PREFIX = 9;

    private Opcode() {
    }

    /** @return the record's name as the specification spells it, for messages */
    static String name(int opcode) {
        return switch (opcode) {
            case HEADER -> "Header";
            case FOOTER -> "Footer";
            case SCHEMA -> "Schema";
            case CHANNEL -> "Channel";
            case MESSAGE -> "Message";
            case CHUNK -> "Chunk";
            case MESSAGE_INDEX -> "Message Index";
            case CHUNK_INDEX -> "Chunk Index";
            case 0x09 -> "Attachment";
            case 0x0A -> "Attachment Index";
            case STATISTICS -> "Statistics";
            case 0x0C -> "Metadata";
            case 0x0D -> "Metadata Index";
            case SUMMARY_OFFSET -> "Summary Offset";
            case DATA_END -> "Data End";
            default -> String.format("opcode 0x%02X", opcode);
        };
    }
}
