#!/usr/bin/env bash
# How many robots of one world keep real time in two processes (docs/performance.md):
# N robots in parallel lanes 1.2 m apart (each drives 7 m to its own checkpoint, none in another's
# way), one `robot --world` process for the world, one `engine --robot-ids 1-N` process, sync timing,
# on a fresh database of the MariaDB server given. Prints N and the robot process's real-time factor.
#
#   bench/fleet-two-process.sh 8 'jdbc:mariadb://127.0.0.1:3306/?user=root&password=' [ENGINE_THREADS] [JFR_DIR]
#
# With JFR_DIR, both processes record a JFR profile there (robot.jfr, engine.jfr).
set -euo pipefail
N="${1:?robots}"
SERVER="${2:-jdbc:mariadb://127.0.0.1:3306/?user=root&password=}"
THREADS="${3:-0}"
JFR_DIR="${4:-}"
JAR="$(dirname "$0")/../app/target/proactive.jar"
WORK="$(mktemp -d /tmp/fleet-two-process.XXXXXX)"
DB="proactive_fleet_bench_$$"
URL="${SERVER/\/\?//$DB?}"

height=$(awk -v n="$N" 'BEGIN { printf "%.1f", n * 1.2 + 1.6 }')
{
	echo "{\"name\": \"lanes-$N\", \"arena\": {\"widthM\": 10.0, \"heightM\": $height}, \"maxSimTimeS\": 120,"
	echo " \"rechargeStation\": {\"x\": -4.5, \"y\": 0.0, \"radiusM\": 0.3}, \"robots\": ["
	for ((k = 1; k <= N; k++)); do
		y=$(awk -v n="$N" -v k="$k" 'BEGIN { printf "%.2f", (k - 1 - (n - 1) / 2) * 1.2 }')
		sep=$([[ $k -lt $N ]] && echo "," || echo "")
		echo "  {\"id\": $k, \"x\": -3.5, \"y\": $y, \"headingDeg\": 0, \"checkpoints\": [{\"x\": 3.5, \"y\": $y}]}$sep"
	done
	echo "]}"
} >"$WORK/lanes.json"

jfr() { # $1: the process's name
	[[ -n "$JFR_DIR" ]] && echo "-XX:StartFlightRecording=filename=$JFR_DIR/$1.jfr,settings=profile" || true
}

java -jar "$JAR" db init --create --db "$URL" >"$WORK/init.log"
java $(jfr engine) -jar "$JAR" engine --db "$URL" --robot-ids "1-$N" --threads "$THREADS" >"$WORK/engine.log" 2>&1 &
engine=$!
java $(jfr robot) -jar "$JAR" robot --db "$URL" --world "$WORK/lanes.json" --out "$WORK/out" >"$WORK/robot.log" 2>&1 || true
kill "$engine" && wait "$engine" || true
factor=$(grep -o '"realTimeFactor": [0-9.]*' "$WORK/out/report.json" | head -1 | awk '{print $2}')
outcome=$(grep -o '"outcome": "[A-Z_]*"' "$WORK/out/report.json" | head -1 | cut -d'"' -f4)
timing=$(tr -d '\n ' <"$WORK/out/report.json" | grep -o '"timing":{[^}]*}')
echo "robots $N: $outcome, ${factor}x real time, per world step $timing (files in $WORK)"
