#!/bin/bash
# CI stand-in for the official MySQL image's entrypoint, on Debian's MariaDB (.ci/compose).
#
# On an empty data directory, as the official image does: creates the system tables, gives root
# MYSQL_ROOT_PASSWORD (on localhost and '%'), creates MYSQL_DATABASE, then runs
# /docker-entrypoint-initdb.d/* in name order on a server that listens on its socket only:
# *.sql through the client on MYSQL_DATABASE, *.sh executed when executable and otherwise
# sourced, with docker_process_sql (the client as root on MYSQL_DATABASE) defined. Then, and on
# every later start, it runs the server on every interface.
set -eo pipefail

DATADIR=/var/lib/mysql
SOCKET=/run/mysqld/mysqld.sock

note() {
	echo "entrypoint: $*"
}

fail() {
	echo "entrypoint: $*" >&2
	exit 1
}

# the client as root over the socket, on MYSQL_DATABASE once it exists (init scripts use this)
docker_process_sql() {
	local database=()
	if [[ -n "${MYSQL_DATABASE:-}" && "${PROACTIVE_DATABASE_CREATED:-}" == yes ]]; then
		database=(--database="$MYSQL_DATABASE")
	fi
	MYSQL_PWD="${MYSQL_ROOT_PASSWORD}" mariadb --protocol=socket --socket="$SOCKET" -uroot "${database[@]}" "$@"
}

# a value inside '...' in SQL: \ and ' doubled
sql_string() {
	local value="${1//\\/\\\\}"
	printf '%s' "${value//\'/\'\'}"
}

initialise() {
	[[ -n "${MYSQL_ROOT_PASSWORD:-}" ]] \
		|| fail "the data directory is empty and MYSQL_ROOT_PASSWORD is not set: it is needed to initialise it"
	if [[ -n "${MYSQL_DATABASE:-}" && ! "$MYSQL_DATABASE" =~ ^[A-Za-z0-9_]+$ ]]; then
		fail "MYSQL_DATABASE must be letters, digits and _: $MYSQL_DATABASE"
	fi
	note "empty data directory: initialising it"
	mariadb-install-db --user=mysql --datadir="$DATADIR" --skip-test-db \
		--auth-root-authentication-method=normal >/dev/null
	mariadbd --user=mysql --datadir="$DATADIR" --socket="$SOCKET" --skip-networking &
	local server=$!
	local tries
	for tries in $(seq 1 60); do
		mariadb-admin --protocol=socket --socket="$SOCKET" -uroot ping >/dev/null 2>&1 && break
		kill -0 "$server" 2>/dev/null || fail "the temporary server ended during the initialisation"
		sleep 0.5
	done
	mariadb-admin --protocol=socket --socket="$SOCKET" -uroot ping >/dev/null 2>&1 \
		|| fail "the temporary server did not answer within 30 s"

	local password
	password="$(sql_string "$MYSQL_ROOT_PASSWORD")"
	# root has no password yet: the first statements go without one. The system tables come with
	# anonymous users and a root on this container's host name: neither is wanted.
	local host
	host="$(sql_string "$HOSTNAME")"
	MYSQL_PWD= mariadb --protocol=socket --socket="$SOCKET" -uroot <<-SQL
		DROP USER IF EXISTS ''@'localhost', ''@'$host', 'root'@'$host';
		ALTER USER 'root'@'localhost' IDENTIFIED BY '$password';
		CREATE USER 'root'@'%' IDENTIFIED BY '$password';
		GRANT ALL ON *.* TO 'root'@'%' WITH GRANT OPTION;
		${MYSQL_DATABASE:+CREATE DATABASE IF NOT EXISTS \`$MYSQL_DATABASE\`;}
	SQL
	PROACTIVE_DATABASE_CREATED=yes

	local f
	for f in /docker-entrypoint-initdb.d/*; do
		case "$f" in
			*.sh)
				if [[ -x "$f" ]]; then
					note "running $f"
					"$f"
				else
					note "sourcing $f"
					# shellcheck disable=SC1090
					. "$f"
				fi
				;;
			*.sql)
				note "running $f"
				docker_process_sql <"$f"
				;;
			*/'*') ;; # an empty directory
			*) note "ignoring $f" ;;
		esac
	done

	MYSQL_PWD="$MYSQL_ROOT_PASSWORD" mariadb-admin --protocol=socket --socket="$SOCKET" -uroot shutdown
	wait "$server"
	note "initialisation done"
}

if [[ "${1:-}" == mariadbd ]]; then
	if [[ -d "$DATADIR/mysql" ]]; then
		note "data directory already initialised: no initialisation"
	else
		initialise
	fi
	shift
	exec mariadbd --user=mysql --datadir="$DATADIR" --socket="$SOCKET" --bind-address=0.0.0.0 --skip-name-resolve "$@"
fi
exec "$@"
