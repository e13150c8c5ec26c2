// Reads the run.mcap of a world with several robots with the format's reference reader (@mcap/core) and checks it
// against the run's trace.jsonl (each line with its "robot"): one /world, and per robot the topics under
// /robot/ID with the same schemas as a one-robot file; each robot's /decision and /pose messages say what its own
// trace lines say, at their simulated times; its /tf and /scan are in its own frame robot_ID/base_link, to which
// /world locks its body; the index finds every message and a seek on one robot's topic; one message of each
// channel validated against Foxglove's JSON Schema. A folder without trace.jsonl (the robot process's) gets every
// check but those against the trace lines, the robots and their step counts taken from its report.json.
// Usage: node check-fleet.mjs RUN_DIR. Exit 0 when all holds.
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
const reported = trace === null ? JSON.parse(readFileSync(join(dir, "report.json"), "utf8")).robots : null;
let passed = 0;
const failures = [];
function check(what, ok, detail = "") {
  if (ok) passed++; else failures.push(`${what}${detail ? ": " + detail : ""}`);
}
const big = (k, v) => (typeof v === "bigint" ? v.toString() : v);
function equal(what, actual, expected) {
  const a = JSON.stringify(actual, big);
  const e = JSON.stringify(expected, big);
  check(what, a === e, `got ${a.slice(0, 300)}, expected ${e.slice(0, 300)}`);
}
const ns = (simTimeS) => BigInt(Math.round(simTimeS * 1000)) * 1000000n;
const mm = (v) => Math.round(v * 1000);

// --- 1. every record in order, CRCs checked ---
const stream = new McapStreamReader({ validateCrcs: true, includeChunks: true });
stream.append(bytes);
const schemas = new Map();
const channels = new Map();
const byTopic = new Map();
const recordCounts = {};
for (let record; (record = stream.nextRecord()) !== undefined;) {
  recordCounts[record.type] = (recordCounts[record.type] ?? 0) + 1;
  if (record.type === "Schema") schemas.set(record.id, record);
  if (record.type === "Channel") channels.set(record.id, record);
  if (record.type === "Message") {
    const topic = channels.get(record.channelId).topic;
    if (!byTopic.has(topic)) byTopic.set(topic, []);
    byTopic.get(topic).push({ logTime: record.logTime, data: JSON.parse(new TextDecoder().decode(record.data)) });
  }
}
check("the stream reader reached the end of the file", stream.done());
for (const type of ["Header", "Chunk", "MessageIndex", "DataEnd", "ChunkIndex", "Statistics", "SummaryOffset", "Footer"]) {
  check(`a ${type} record`, (recordCounts[type] ?? 0) > 0);
}

// --- 2. channels: /world, and each robot's topics under /robot/ID ---
const ids = trace !== null ? [...new Set(trace.map((r) => r.robot))].sort((a, b) => a - b)
  : reported.map((r) => r.id).sort((a, b) => a - b);
check("the run has several robots", ids.length > 1, JSON.stringify(ids));
const perRobot = {
  tf: "foxglove.FrameTransform", pose: "foxglove.PoseInFrame", pose_estimate: "foxglove.PoseInFrame",
  scan: "foxglove.LaserScan", map: "foxglove.Grid", decision: "proactive.Decision", battery: "proactive.Battery",
  events: "foxglove.Log",
};
const expectedChannels = { "/world": "foxglove.SceneUpdate" };
for (const id of ids) for (const [t, s] of Object.entries(perRobot)) expectedChannels[`/robot/${id}/${t}`] = s;
const actualChannels = {};
for (const c of channels.values()) actualChannels[c.topic] = schemas.get(c.schemaId).name;
equal("channels and their schemas", actualChannels, expectedChannels);
equal("one schema record per schema name", schemas.size, new Set(Object.values(expectedChannels)).size);

// --- 3. /world: one message at time 0, each robot's body locked to its own frame ---
const world = byTopic.get("/world") ?? [];
check("/world comes once, at time 0", world.length === 1 && world[0].logTime === 0n);
const bodies = Object.fromEntries(world[0].data.entities.filter((e) => e.frame_locked).map((e) => [e.id, e.frame_id]));
equal("/world's robot bodies and their frames", bodies, Object.fromEntries(ids.map((id) => [`robot_${id}`, `robot_${id}/base_link`])));

// --- 4. each robot's messages against its own trace lines ---
for (const id of ids) {
  const topic = (t) => byTopic.get(`/robot/${id}/${t}`) ?? [];
  if (trace === null) { // the robot process's folder: a message per control step, as its report counts them
    const steps = reported.find((r) => r.id === id).controlSteps;
    for (const t of ["decision", "pose", "tf", "battery"]) equal(`robot ${id}: a /${t} message per control step`, topic(t).length, steps);
  }
  const lines = trace === null ? [] : trace.filter((r) => r.robot === id);
  if (trace !== null) {
    for (const t of ["decision", "pose", "tf", "battery"]) equal(`robot ${id}: a /${t} message per trace line`, topic(t).length, lines.length);
  }
  let bad = "";
  lines.forEach((r, i) => {
    const d = topic("decision")[i];
    const p = topic("pose")[i];
    const want = { t: ns(r.simTimeS), iteration: r.iteration, winner: r.winner, command: r.command, x: mm(r.pose.xM), y: mm(r.pose.yM) };
    const got = { t: d.logTime, iteration: d.data.iteration, winner: d.data.winner, command: d.data.command,
      x: mm(p.data.pose.position.x), y: mm(p.data.pose.position.y) };
    if (bad === "" && JSON.stringify(got, big) !== JSON.stringify(want, big)) bad = `${JSON.stringify(got, big)} vs ${JSON.stringify(want, big)}`;
  });
  check(`robot ${id}: each /decision and /pose says what its trace line says`, bad === "", bad);
  check(`robot ${id}: /tf moves robot_${id}/base_link`, topic("tf").every((m) => m.data.child_frame_id === `robot_${id}/base_link`
    && m.data.parent_frame_id === "world"));
  check(`robot ${id}: /scan in robot_${id}/base_link`, topic("scan").length > 0
    && topic("scan").every((m) => m.data.frame_id === `robot_${id}/base_link`));
  if (trace !== null) {
    equal(`robot ${id}: /events as its trace lines' events`, topic("events").map((m) => m.data.message),
      lines.flatMap((r) => [...r.events.map((e) => JSON.stringify(e)), ...(r.reason ? [r.reason] : [])]));
  }
}

// --- 5. the index: every message, and a seek on one robot's decisions ---
const readable = { size: async () => BigInt(bytes.length), read: async (o, s) => bytes.subarray(Number(o), Number(o + s)) };
const indexed = await McapIndexedReader.Initialize({ readable });
const total = [...byTopic.values()].reduce((n, a) => n + a.length, 0);
let indexedTotal = 0;
for await (const _ of indexed.readMessages({ validateCrcs: true })) indexedTotal++;
equal("messages read through the index", indexedTotal, total);
const second = ids[1];
const decided = byTopic.get(`/robot/${second}/decision`);
const from = decided[Math.floor(decided.length / 2)].logTime;
const to = from + 2000000000n;
const seeked = [];
for await (const m of indexed.readMessages({ topics: [`/robot/${second}/decision`], startTime: from, endTime: to })) {
  seeked.push(JSON.parse(new TextDecoder().decode(m.data)).iteration);
}
const inWindow = decided.filter((d) => d.logTime >= from && d.logTime <= to).map((d) => d.data.iteration);
equal(`a seek on /robot/${second}/decision finds that stretch's decisions, in order`, seeked, inWindow);

// --- 6. JSON Schemas: Foxglove's own, and the file's own, on one message of each channel ---
const ajv = new Ajv({ strict: false, allErrors: true });
for (const [topic, name] of Object.entries(expectedChannels)) {
  const messages = byTopic.get(topic) ?? [];
  if (messages.length === 0) continue;
  const m = messages[messages.length - 1];
  if (name.startsWith("foxglove.")) {
    const validate = ajv.compile(foxgloveSchemas[name.slice("foxglove.".length)]);
    check(`${topic} against Foxglove's ${name}`, validate(m.data), ajv.errorsText(validate.errors));
  }
  const own = [...schemas.values()].find((s) => s.name === name);
  const validateOwn = ajv.compile(JSON.parse(new TextDecoder().decode(own.data)));
  check(`${topic} against the file's own ${name}`, validateOwn(m.data), ajv.errorsText(validateOwn.errors));
}

for (const f of failures) console.log(`FAILED ${f}`);
console.log(`mcap-reader: ${ids.length} robots, ${channels.size} channels, ${total} messages; ${recordCounts.Chunk} chunks`);
console.log(`${passed} passed, ${failures.length} failed`);
process.exit(failures.length === 0 ? 0 : 1);
