#!/bin/bash
# A three-node MariaDB Galera cluster on this machine, for trying a fleet on it (and for CI):
# nodes 1-3 listen on 127.0.0.1 ports BASE+1..BASE+3 (default 13307-13309; Galera's own traffic on
# BASE+1261, +1361, +1461 and the two ports after each: 14567-14569, 14667-14669, 14767-14769),
# each with its data directory, socket, pid file and log in DIR/nodeN (DIR must not exist or be
# empty). Root may log in over TCP with an empty password, as on the test server.
#   deploy/galera/three-node-cluster.sh start DIR [BASE]
#   deploy/galera/three-node-cluster.sh kill DIR N       # kill -9 of node N (a crash)
#   deploy/galera/three-node-cluster.sh rejoin DIR N     # node N starts again and catches up
#   deploy/galera/three-node-cluster.sh stop DIR         # every node stopped by its pid
# Needs Debian's mariadb-server, galera-4 and rsync; runs as root, the servers as user mysql.
set -euo pipefail
what=${1:?start, kill, rejoin or stop}
dir=$(realpath -m "${2:?the cluster folder}")

node_port() { echo $(( $(cat "$dir/base") + $1 )); }
gcomm_port() { echo $(( $(cat "$dir/base") + 1161 + 100 * $1 )); }

write_conf() { # N
  local n=$1 g
  g=$(gcomm_port "$n")
  cat > "$dir/node$n/my.cnf" <<CONF
[mariadbd]
user=mysql
datadir=$dir/node$n/data
socket=$dir/node$n/mysqld.sock
pid-file=$dir/node$n/mysqld.pid
log-error=$dir/node$n/error.log
port=$(node_port "$n")
bind-address=127.0.0.1
skip-log-bin
binlog_format=ROW
default_storage_engine=InnoDB
innodb_autoinc_lock_mode=2
innodb_buffer_pool_size=64M
innodb_flush_log_at_trx_commit=2
max_connections=300
wsrep_on=ON
wsrep_provider=/usr/lib/galera/libgalera_smm.so
wsrep_cluster_name=proactive
wsrep_cluster_address=gcomm://127.0.0.1:$(gcomm_port 1),127.0.0.1:$(gcomm_port 2),127.0.0.1:$(gcomm_port 3)
wsrep_node_name=node$n
wsrep_node_address=127.0.0.1:$g
wsrep_provider_options="gmcast.listen_addr=tcp://127.0.0.1:$g;ist.recv_addr=127.0.0.1:$((g + 1))"
wsrep_sst_receive_address=127.0.0.1:$((g + 2))
wsrep_sst_method=rsync
CONF
}

up() { # N: answers and is synced
  mariadb -uroot -h127.0.0.1 -P"$(node_port "$1")" -N -e "SHOW STATUS LIKE 'wsrep_local_state_comment'" 2>/dev/null \
    | grep -q Synced
}

wait_up() { # N
  for _ in $(seq 600); do
    up "$1" && return 0
    sleep 0.1
  done
  echo "node $1 did not become Synced within 60 s; its log: $dir/node$1/error.log" >&2
  tail -20 "$dir/node$1/error.log" >&2 || true
  return 1
}

start_node() { # N [extra mariadbd options]
  local n=$1
  shift
  mariadbd --defaults-file="$dir/node$n/my.cnf" "$@" >/dev/null 2>&1 &
  wait_up "$n"
}

. "$(dirname "$0")/../stop-by-pid.sh"

case $what in
start)
  if [ -n "$(ls -A "$dir" 2>/dev/null)" ]; then
    echo "$dir is not empty: stop the cluster in it and remove it, or give another folder" >&2
    exit 2
  fi
  mkdir -p "$dir"
  echo "${3:-13306}" > "$dir/base"
  for n in 1 2 3; do
    mkdir -p "$dir/node$n/data"
    write_conf "$n"
  done
  chown -R mysql:mysql "$dir"/node1 "$dir"/node2 "$dir"/node3
  if ! runuser -u mysql -- test -w "$dir/node1/data"; then
    echo "user mysql cannot write in $dir (a parent folder closed to it?): the servers run as mysql" >&2
    exit 1
  fi
  if ! mariadb-install-db --defaults-file="$dir/node1/my.cnf" --auth-root-authentication-method=normal \
    --skip-test-db > "$dir/install.log" 2>&1; then
    cat "$dir/install.log" >&2
    exit 1
  fi
  start_node 1 --wsrep-new-cluster
  start_node 2
  start_node 3
  size=$(mariadb -uroot -h127.0.0.1 -P"$(node_port 1)" -N -e "SHOW STATUS LIKE 'wsrep_cluster_size'" | cut -f2)
  echo "galera cluster of $size nodes up in $dir: 127.0.0.1:$(node_port 1),127.0.0.1:$(node_port 2),127.0.0.1:$(node_port 3)"
  ;;
kill)
  n=${3:?which node}
  kill -9 "$(cat "$dir/node$n/mysqld.pid")"
  rm -f "$dir/node$n/mysqld.pid"
  echo "node $n killed"
  ;;
rejoin)
  n=${3:?which node}
  start_node "$n"
  echo "node $n rejoined"
  ;;
stop)
  for n in 3 2 1; do
    stop_pid "node $n" "$dir/node$n/mysqld.pid"
  done
  ;;
*)
  echo "usage: $0 start|kill|rejoin|stop DIR ..." >&2
  exit 2
  ;;
esac
