// Reads a run's run.mcap with the format's reference reader (@mcap/core) and checks it against the
// run's trace.jsonl: every record read in order with CRCs checked, each channel's schema and
// message count, the messages' content, a seek by time through the index, and one message of each
// channel validated against Foxglove's own JSON Schema (@foxglove/schemas) and against the schema
// the file carries. A folder without trace.jsonl (the robot process's) gets every check but those
// against the trace. Usage: node check-run.mjs RUN_DIR. Exit 0 when all holds, 1 otherwise.
import { existsSync, readFileSync } from "node:fs";
import { join } from "node:path";
import { McapIndexedReader, McapStreamReader } from "@mcap/core";
import Ajv from "ajv";
import foxgloveSchemas from "@foxglove/schemas/jsonschema.js";

const dir = process.argv[2];
const bytes = new Uint8Array(readFileSync(join(dir, "run.mcap")));
const traceFile = join(dir, "trace.jsonl");
const trace = existsSync(traceFile)
  ? readFileSync(traceFile, "utf8").split("\n").filter((l) => l.length > 0).map((l) => JSON.parse(l))
  : null;
let passed = 0;
const failures = [];

function check(what, ok, detail = "") {
  if (ok) {
    passed++;
  } else {
    failures.push(`${what}${detail ? ": " + detail : ""}`);
  }
}
function equal(what, actual, expected) {
  const a = JSON.stringify(actual);
  const e = JSON.stringify(expected);
  check(what, a === e, `got ${a.slice(0, 300)}, expected ${e.slice(0, 300)}`);
}
const ns = (simTimeS) => BigInt(Math.round(simTimeS * 1000)) * 1000000n;
const mm = (v) => Math.round(v * 1000);
const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);

// --- 1. every record, in file order, with the stream reader (chunk CRCs checked) ---
const stream = new McapStreamReader({ validateCrcs: true, includeChunks: true });
stream.append(bytes);
const recordCounts = {};
const schemas = new Map();
const channels = new Map();
const messagesByTopic = new Map();
let header;
let dataEnd;
for (let record; (record = stream.nextRecord()) !== undefined;) {
  recordCounts[record.type] = (recordCounts[record.type] ?? 0) + 1;
  if (record.type === "Header") header = record;
  if (record.type === "DataEnd") dataEnd = record;
  if (record.type === "Schema") schemas.set(record.id, record);
  if (record.type === "Channel") channels.set(record.id, record);
  if (record.type === "Message") {
    const topic = channels.get(record.channelId).topic;
    if (!messagesByTopic.has(topic)) messagesByTopic.set(topic, []);
    messagesByTopic.get(topic).push({ logTime: record.logTime, data: JSON.parse(new TextDecoder().decode(record.data)) });
  }
}
check("the stream reader reached the end of the file", stream.done());
equal("Header", { profile: header.profile, library: header.library }, { profile: "", library: "proactive-robotics mcap 1" });
for (const type of ["Header", "Chunk", "MessageIndex", "DataEnd", "ChunkIndex", "Statistics", "SummaryOffset", "Footer"]) {
  check(`a ${type} record`, (recordCounts[type] ?? 0) > 0);
}
const dataEndAt = Number(new McapIndexedReaderOffsets(bytes).dataEnd);
check("the data section's CRC32", dataEnd.dataSectionCrc === crc32(bytes.subarray(0, dataEndAt)),
  `${dataEnd.dataSectionCrc} vs ${crc32(bytes.subarray(0, dataEndAt))}`);

// --- 2. channels and schemas ---
const expectedChannels = {
  "/world": "foxglove.SceneUpdate", "/tf": "foxglove.FrameTransform", "/pose": "foxglove.PoseInFrame",
  "/pose_estimate": "foxglove.PoseInFrame", "/scan": "foxglove.LaserScan", "/map": "foxglove.Grid",
  "/decision": "proactive.Decision", "/battery": "proactive.Battery", "/events": "foxglove.Log",
};
const actualChannels = {};
for (const c of channels.values()) {
  const s = schemas.get(c.schemaId);
  actualChannels[c.topic] = s.name;
  equal(`${c.topic}'s encodings`, [c.messageEncoding, s.encoding], ["json", "jsonschema"]);
}
equal("channels and their schemas", actualChannels, expectedChannels);

// --- 3. counts and content against trace.jsonl ---
const count = (topic) => (messagesByTopic.get(topic) ?? []).length;
const actualCounts = {};
for (const topic of Object.keys(expectedChannels)) actualCounts[topic] = count(topic);
const total = Object.values(actualCounts).reduce((a, b) => a + b, 0);
let expectedCounts = actualCounts;
check("/world comes at time 0", count("/world") === 1 && messagesByTopic.get("/world")[0].logTime === 0n);
for (const topic of ["/tf", "/pose", "/battery"]) equal(`a ${topic} message per decision`, count(topic), count("/decision"));
if (trace !== null) {
  const hasBelief = trace.some((r) => "belief" in r);
  const expectedEstimates = [];
  let last = null;
  for (const r of trace) {
    let b = null;
    if (hasBelief) b = r.belief ?? null;
    else if (r.seen.gps !== null && r.seen.headingRad !== null) b = { xM: r.seen.gps.xM, yM: r.seen.gps.yM, headingRad: r.seen.headingRad };
    if (b === null) continue;
    const key = [mm(b.xM), mm(b.yM), mm(b.headingRad)].join();
    if (hasBelief || key !== last) expectedEstimates.push({ t: ns(r.simTimeS), b });
    last = key;
  }
  const expectedMaps = [];
  {
    let pending = false;
    let lastMap = null;
    for (const r of trace) {
      if (Array.isArray(r.mapDelta) && r.mapDelta.length > 0) pending = true;
      const t = Math.round(r.simTimeS * 1000);
      if (pending && (lastMap === null || t - lastMap >= 1000)) {
        expectedMaps.push(t);
        pending = false;
        lastMap = t;
      }
    }
    if (pending) expectedMaps.push(Math.round(trace[trace.length - 1].simTimeS * 1000));
  }
  expectedCounts = {
    "/world": 1, "/tf": trace.length, "/pose": trace.length, "/pose_estimate": expectedEstimates.length,
    "/scan": trace.filter((r) => r.seen.scanM !== null).length, "/map": expectedMaps.length,
    "/decision": trace.length, "/battery": trace.length,
    "/events": trace.reduce((n, r) => n + r.events.length + (r.reason ? 1 : 0), 0),
  };
  equal("messages per channel", actualCounts, expectedCounts);

  const decisions = messagesByTopic.get("/decision");
  const poses = messagesByTopic.get("/pose");
  let contentOk = true;
  let firstBad = "";
  trace.forEach((r, i) => {
    const d = decisions[i];
    const p = poses[i];
    const want = {
      t: ns(r.simTimeS), iteration: r.iteration, winner: r.winner, command: r.command,
      suggestions: Object.entries(r.suggestions).map(([scenario, command]) => ({ scenario, command })),
      priorities: Object.entries(r.priorities).map(([scenario, priority]) => ({ scenario, priority })),
      x: mm(r.pose.xM), y: mm(r.pose.yM),
    };
    const got = {
      t: d.logTime, iteration: d.data.iteration, winner: d.data.winner, command: d.data.command,
      suggestions: d.data.suggestions, priorities: d.data.priorities,
      x: mm(p.data.pose.position.x), y: mm(p.data.pose.position.y),
    };
    // the heading back from the quaternion, to the trace's milliradian
    const q = p.data.pose.orientation;
    const headingOff = Math.abs(Math.atan2(Math.sin(2 * Math.atan2(q.z, q.w) - r.pose.headingRad),
      Math.cos(2 * Math.atan2(q.z, q.w) - r.pose.headingRad)));
    if (contentOk && (headingOff > 0.0015 || JSON.stringify(got, (k, v) => typeof v === "bigint" ? v.toString() : v)
        !== JSON.stringify(want, (k, v) => typeof v === "bigint" ? v.toString() : v) || p.logTime !== want.t)) {
      contentOk = false;
      firstBad = `iteration ${r.iteration}: ${JSON.stringify(got, (k, v) => typeof v === "bigint" ? v.toString() : v)} vs ${JSON.stringify(want, (k, v) => typeof v === "bigint" ? v.toString() : v)}`;
    }
  });
  check("each /decision and /pose message says what its trace.jsonl line says, at its simulated time", contentOk, firstBad);
  const events = trace.flatMap((r) => [...r.events.map((e) => JSON.stringify(e)), ...(r.reason ? [r.reason] : [])]);
  equal("/events in order, as trace.jsonl's events", (messagesByTopic.get("/events") ?? []).map((m) => m.data.message), events);
  const estimates = messagesByTopic.get("/pose_estimate");
  check("/pose_estimate holds the engine's belief", expectedEstimates.every((e, i) => estimates[i].logTime === e.t
    && mm(estimates[i].data.pose.position.x) === mm(e.b.xM) && mm(estimates[i].data.pose.position.y) === mm(e.b.yM)));
  const scans = messagesByTopic.get("/scan");
  const scanned = trace.filter((r) => r.seen.scanM !== null);
  check("/scan holds the rays the engine read", scanned.every((r, i) => {
    const rays = scans[i].data.ranges.filter((v) => v > 0); // a bearing without a ray reads 0
    return rays.length === r.seen.scanM.filter((v) => v !== null).length && scans[i].logTime === ns(r.simTimeS);
  }));
}

// --- 4. the index: summary, statistics, and a seek by time ---
const readable = {
  size: async () => BigInt(bytes.length),
  read: async (offset, size) => bytes.subarray(Number(offset), Number(offset + size)),
};
const indexed = await McapIndexedReader.Initialize({ readable });
equal("Statistics: messages, chunks", [Number(indexed.statistics.messageCount), indexed.statistics.chunkCount],
  [total, recordCounts.Chunk]);
equal("Chunk Index records", indexed.chunkIndexes.length, recordCounts.Chunk);
const statsByTopic = {};
for (const [id, n] of indexed.statistics.channelMessageCounts) statsByTopic[indexed.channelsById.get(id).topic] = Number(n);
equal("Statistics: messages per channel", statsByTopic, Object.fromEntries(Object.entries(expectedCounts).filter(([, n]) => n > 0)));
check("the footer's summary CRC32", (() => {
  const footerAt = bytes.length - 8 - 29;
  const summaryStart = Number(view.getBigUint64(footerAt + 9, true));
  return view.getUint32(footerAt + 25, true) === crc32(bytes.subarray(summaryStart, footerAt + 25));
})());
let indexedTotal = 0;
for await (const _ of indexed.readMessages({ validateCrcs: true })) indexedTotal++;
equal("messages read through the index", indexedTotal, total);
const decided = messagesByTopic.get("/decision").map((m) => ({ t: m.logTime, iteration: m.data.iteration }));
const from = decided[Math.floor(decided.length / 2)].t;
const to = from + 2000000000n;
const seeked = [];
for await (const m of indexed.readMessages({ topics: ["/decision"], startTime: from, endTime: to })) {
  seeked.push({ t: m.logTime, iteration: JSON.parse(new TextDecoder().decode(m.data)).iteration });
}
const inWindow = decided.filter((d) => d.t >= from && d.t <= to);
check("a seek to the middle of the run through the index finds that stretch's decisions, in order",
  seeked.length === inWindow.length && seeked.length > 0 && seeked.every((s, i) => s.iteration === inWindow[i].iteration),
  `${seeked.length} found, ${inWindow.length} expected`);
const lastPose = [];
for await (const m of indexed.readMessages({ topics: ["/pose"], reverse: true })) {
  lastPose.push(m);
  break;
}
check("reading backwards starts at the last pose", lastPose.length === 1 && lastPose[0].logTime === decided[decided.length - 1].t);

// --- 5. JSON Schemas: Foxglove's own for its well-known ones, and the file's own for every channel ---
const ajv = new Ajv({ strict: false, allErrors: true });
const foxgloveName = (name) => name.startsWith("foxglove.") ? name.slice("foxglove.".length) : null;
for (const [topic, name] of Object.entries(expectedChannels)) {
  const messages = messagesByTopic.get(topic) ?? [];
  if (messages.length === 0) continue;
  const samples = [messages[0], messages[messages.length - 1]];
  const short = foxgloveName(name);
  if (short !== null) {
    const validate = ajv.compile(foxgloveSchemas[short]);
    for (const m of samples) check(`${topic} against Foxglove's ${name}`, validate(m.data), ajv.errorsText(validate.errors));
  }
  const own = [...schemas.values()].find((s) => s.name === name);
  const validateOwn = ajv.compile(JSON.parse(new TextDecoder().decode(own.data)));
  const bad = messages.find((m) => !validateOwn(m.data));
  check(`every ${topic} message against the file's own ${name}`, bad === undefined, ajv.errorsText(validateOwn.errors));
}

for (const f of failures) console.log(`FAILED ${f}`);
console.log(`mcap-reader: ${Object.entries(actualCounts).map(([t, n]) => `${t} ${n}`).join(", ")}; ${recordCounts.Chunk} chunks`);
console.log(`${passed} passed, ${failures.length} failed`);
process.exit(failures.length === 0 ? 0 : 1);

/** CRC-32 (IEEE, reflected, as the MCAP specification uses), written here: Node 18 has no zlib.crc32. */
function crc32(data) {
  let crc = 0xffffffff;
  for (let i = 0; i < data.length; i++) {
    crc ^= data[i];
    for (let k = 0; k < 8; k++) crc = (crc >>> 1) ^ (0xedb88320 & -(crc & 1));
  }
  return (crc ^ 0xffffffff) >>> 0;
}

/** Where Data End starts: the summary's start minus the 13 bytes of a Data End record. */
function McapIndexedReaderOffsets(b) {
  const footerAt = b.length - 8 - 29;
  const v = new DataView(b.buffer, b.byteOffset, b.byteLength);
  return { dataEnd: v.getBigUint64(footerAt + 9, true) - 13n };
}
