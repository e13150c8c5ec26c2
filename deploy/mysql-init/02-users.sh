#!/bin/bash
# proactive-robotics: creates the engine's and the robot's least-privilege users.
#
# Sourced by the MySQL image's entrypoint (docker-entrypoint-initdb.d, after 01-schema.sql),
# which provides docker_process_sql (the mysql client as root, on MYSQL_DATABASE). Fills the
# template deploy/users.sql (mounted at PROACTIVE_USERS_SQL) from the environment:
#   MYSQL_DATABASE, ENGINE_DB_PASSWORD, ROBOT_DB_PASSWORD (required),
#   ENGINE_DB_USER (proactive_engine), ROBOT_DB_USER (proactive_robot), PROACTIVE_DB_HOST (%).
# The end-to-end tests source this very file with a docker_process_sql of their own.

proactive_create_users() {
	local template="${PROACTIVE_USERS_SQL:-/proactive/users.sql}"
	local database="${MYSQL_DATABASE:?MYSQL_DATABASE must name the database}"
	local engine_user="${ENGINE_DB_USER:-proactive_engine}"
	local robot_user="${ROBOT_DB_USER:-proactive_robot}"
	local host="${PROACTIVE_DB_HOST:-%}"
	local engine_password="${ENGINE_DB_PASSWORD:?set ENGINE_DB_PASSWORD (see .env.example)}"
	local robot_password="${ROBOT_DB_PASSWORD:?set ROBOT_DB_PASSWORD (see .env.example)}"
	# the viewer (`watch`, SELECT only) is optional: no VIEWER_DB_PASSWORD, no viewer user
	local viewer_user="${VIEWER_DB_USER:-proactive_viewer}"
	local viewer_password="${VIEWER_DB_PASSWORD:-}"
	local value
	for value in "$engine_password" "$robot_password" "$viewer_password"; do
		# the values go inside '...' literals: refuse what would end or escape one
		case "$value" in
			*"'"* | *'\'*) echo "02-users.sh: a password must not contain ' or \\" >&2; return 1 ;;
		esac
	done
	for value in "$database" "$engine_user" "$robot_user" "$viewer_user"; do
		if [[ ! "$value" =~ ^[A-Za-z0-9_]+$ ]]; then
			echo "02-users.sh: database and user names are letters, digits and _: $value" >&2
			return 1
		fi
	done
	if [[ ! "$host" =~ ^[A-Za-z0-9_.%-]+$ ]]; then
		echo "02-users.sh: bad host pattern: $host" >&2
		return 1
	fi
	local sql
	if [[ -n "$viewer_password" ]]; then
		sql="$(cat "$template")" || return 1
	else
		sql="$(grep -v '@VIEWER_' "$template")" || return 1
	fi
	# quoted replacements: a password may hold & or other pattern characters
	sql="${sql//@DATABASE@/"$database"}"
	sql="${sql//@HOST@/"$host"}"
	sql="${sql//@ENGINE_USER@/"$engine_user"}"
	sql="${sql//@ENGINE_PASSWORD@/"$engine_password"}"
	sql="${sql//@ROBOT_USER@/"$robot_user"}"
	sql="${sql//@ROBOT_PASSWORD@/"$robot_password"}"
	sql="${sql//@VIEWER_USER@/"$viewer_user"}"
	sql="${sql//@VIEWER_PASSWORD@/"$viewer_password"}"
	docker_process_sql <<<"$sql" || return 1
	echo "02-users.sh: users $engine_user and $robot_user${viewer_password:+ and $viewer_user} granted on $database"
}

proactive_create_users
