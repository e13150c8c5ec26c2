/**
 * A small writer ({@link org.proactiverobotics.mcap.McapWriter}) and checker
 * ({@link org.proactiverobotics.mcap.McapCheck}) of MCAP files, the recording format of the Foxglove
 * and ROS 2 tools, after the format's specification (major version 0): magic, Header, Schema,
 * Channel and Message records inside uncompressed Chunks, a Message Index after each chunk, Data
 * End, a summary section (Schema, Channel, Statistics, Chunk Index) with Summary Offsets, the Footer
 * and its CRCs. It knows nothing of robots: the caller names the schemas, channels and bytes.
 */
package org.proactiverobotics.mcap;
