#!/bin/sh
# A throw-away PostgreSQL server for benches and tests: initdb in a fresh temp
# folder, listening on loopback only (a unix socket inside that folder and
# 127.0.0.1 on a free port), stopped and deleted again on exit.
#
# Two ways to use it (POSIX sh; bash and dash both work):
#
#   sh scripts/pg-throwaway.sh run CMD [ARGS...]   (executed under this file name)
#       starts a server, runs CMD with the connection exported (below), then
#       stops the server and deletes its folder, whatever CMD exits with (the
#       exit status is CMD's). e.g.
#       sh scripts/pg-throwaway.sh run psql -c 'select version()'
#       sh scripts/pg-throwaway.sh run sh -c 'cargo test --features postgres'
#
#   . scripts/pg-throwaway.sh          # defines functions only, starts nothing
#   pg_throwaway_start                 # starts, exports, installs an EXIT trap
#   psql -c 'create extension pgrouting'
#   pg_throwaway_stop                  # (also run by the trap; safe to repeat)
#
#   pg_throwaway_install [EXT...]      # as root without the server binaries (a
#       fresh CI machine): apt-get installs `postgresql` and, for each EXT,
#       `postgresql-<major>-<EXT>` (e.g. pgrouting, postgis-3). Needs apt-get.
#
# Exported while the server runs: PGHOST (the socket folder), PGPORT, PGUSER,
# PGDATABASE, PGPASSWORD, so plain `psql`/`pgbench` connect; DATABASE_URL
# (postgresql://USER:PASSWORD@127.0.0.1:PORT/DB, for TCP clients); PG_THROWAWAY_DIR.
# `run` also prints DATABASE_URL on stderr. The socket folder trusts local
# connections (it is mode 0700, so only its owner and root reach it); TCP
# needs the password (scram-sha-256), which is random per start.
#
# Root: initdb and postgres refuse to run as root, so as root the server runs
# as PG_THROWAWAY_OS_USER (default: the `postgres` account the Debian package
# creates, else a system user `nrgdb-pg` created here) via runuser; the
# database superuser is still named after the calling user (PGUSER=root), so
# the caller's clients need no changes. Not root: everything runs as you.
#
# Settings (environment, all optional):
#   PG_THROWAWAY_DB      database to create (default nrgdb)
#   PG_THROWAWAY_PORT    TCP port (default: a random free one, retried on clash)
#   PG_THROWAWAY_OS_USER account to run the server as when root
#   PG_THROWAWAY_BINDIR  folder with initdb/pg_ctl/psql/pgbench (default: PATH,
#                        then the newest /usr/lib/postgresql/*/bin); exported
#                        as the one in use while the server runs
#   PG_THROWAWAY_TRAP    0: pg_throwaway_start installs no EXIT/INT/TERM trap
#   PG_THROWAWAY_CONF    extra postgresql.conf lines (newline separated)
# The server runs with fsync, synchronous_commit and full_page_writes off: it
# holds nothing worth keeping, and that keeps it fast on a shared machine.

_pgt_say() { printf 'pg-throwaway: %s\n' "$*" >&2; }

_pgt_bindir() {
    if [ -n "${PG_THROWAWAY_BINDIR:-}" ]; then
        printf '%s\n' "$PG_THROWAWAY_BINDIR"
        return 0
    fi
    _pgt_found=$(command -v initdb 2>/dev/null || true)
    if [ -n "$_pgt_found" ] && command -v pg_ctl >/dev/null 2>&1; then
        dirname "$(readlink -f "$_pgt_found")"
        return 0
    fi
    # Debian keeps the server binaries off PATH; take the newest major version.
    _pgt_found=$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -t/ -k4,4n | tail -n 1)
    if [ -n "$_pgt_found" ] && [ -x "$_pgt_found/initdb" ]; then
        printf '%s\n' "$_pgt_found"
        return 0
    fi
    return 1
}

# The server's major version (e.g. 15), from its initdb.
pg_throwaway_major() {
    _pgt_b=$(_pgt_bindir) || return 1
    "$_pgt_b/initdb" --version | sed -n 's/.* \([0-9][0-9]*\)[.0-9]*.*/\1/p' | head -n 1
}

# apt-get installs the server (if missing) and postgresql-<major>-EXT per EXT.
pg_throwaway_install() {
    if [ "$(id -u)" != 0 ] || ! command -v apt-get >/dev/null 2>&1; then
        _pgt_say "install needs root and apt-get; install PostgreSQL (and $*) by hand"
        return 1
    fi
    _pgt_updated=
    if ! _pgt_bindir >/dev/null; then
        apt-get update -qq && _pgt_updated=1
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq postgresql >/dev/null || return 1
    fi
    _pgt_major=$(pg_throwaway_major) || return 1
    _pgt_pkgs=
    for _pgt_ext in "$@"; do
        _pgt_pkgs="$_pgt_pkgs postgresql-$_pgt_major-$_pgt_ext"
    done
    [ -z "$_pgt_pkgs" ] && return 0
    # Skip apt when every package is installed already.
    # shellcheck disable=SC2086
    _pgt_have=$(dpkg-query -W -f='${Status}\n' $_pgt_pkgs 2>/dev/null | grep -c 'install ok installed')
    if [ "$_pgt_have" -ne "$#" ]; then
        [ -n "$_pgt_updated" ] || apt-get update -qq || return 1
        # shellcheck disable=SC2086
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $_pgt_pkgs >/dev/null || return 1
    fi
}

# Runs "$@" as the server's account (root: via runuser; else directly), in the
# data folder's parent so a cwd the account cannot read does not matter.
_pgt_as() {
    if [ -n "${_PGT_OS_USER:-}" ]; then
        (cd "$PG_THROWAWAY_DIR" && runuser -u "$_PGT_OS_USER" -- "$@")
    else
        (cd "$PG_THROWAWAY_DIR" && "$@")
    fi
}

_pgt_random() { od -An -N4 -tu4 /dev/urandom | tr -d ' \n'; }

pg_throwaway_start() {
    if [ -n "${PG_THROWAWAY_DIR:-}" ] && [ -d "$PG_THROWAWAY_DIR" ]; then
        _pgt_say "already running in $PG_THROWAWAY_DIR"
        return 0
    fi
    _PGT_BIN=$(_pgt_bindir) || {
        _pgt_say "no initdb found (install PostgreSQL, or pg_throwaway_install as root)"
        return 1
    }
    _PGT_OS_USER=
    if [ "$(id -u)" = 0 ]; then
        _PGT_OS_USER=${PG_THROWAWAY_OS_USER:-}
        if [ -z "$_PGT_OS_USER" ]; then
            if id postgres >/dev/null 2>&1; then
                _PGT_OS_USER=postgres
            else
                _PGT_OS_USER=nrgdb-pg
                id "$_PGT_OS_USER" >/dev/null 2>&1 ||
                    useradd --system --no-create-home --shell /usr/sbin/nologin "$_PGT_OS_USER" ||
                    return 1
            fi
        fi
        command -v runuser >/dev/null 2>&1 || { _pgt_say "runuser missing (util-linux)"; return 1; }
    fi
    # A short path: unix socket paths are limited to ~107 bytes. /tmp when
    # root, since the server's account must be able to reach the folder.
    if [ -n "$_PGT_OS_USER" ]; then _pgt_tmp=/tmp; else _pgt_tmp=${TMPDIR:-/tmp}; fi
    PG_THROWAWAY_DIR=$(mktemp -d "$_pgt_tmp/pgt.XXXXXX") || return 1
    export PG_THROWAWAY_DIR
    if [ "${PG_THROWAWAY_TRAP:-1}" != 0 ]; then
        trap 'pg_throwaway_stop' EXIT
        trap 'exit 130' INT
        trap 'exit 143' TERM
    fi
    _pgt_dbuser=$(id -un)
    _pgt_password=$(od -An -N16 -tx1 /dev/urandom | tr -d ' \n')
    printf '%s\n' "$_pgt_password" >"$PG_THROWAWAY_DIR/pwfile"
    chmod 600 "$PG_THROWAWAY_DIR/pwfile"
    [ -n "$_PGT_OS_USER" ] && chown "$_PGT_OS_USER" "$PG_THROWAWAY_DIR" "$PG_THROWAWAY_DIR/pwfile"
    if ! _pgt_as "$_PGT_BIN/initdb" -D "$PG_THROWAWAY_DIR/data" -U "$_pgt_dbuser" \
        --pwfile="$PG_THROWAWAY_DIR/pwfile" --auth-local=trust --auth-host=scram-sha-256 \
        -E UTF8 --locale=C.UTF-8 --no-sync >"$PG_THROWAWAY_DIR/initdb.log" 2>&1; then
        cat "$PG_THROWAWAY_DIR/initdb.log" >&2
        pg_throwaway_stop
        return 1
    fi
    rm -f "$PG_THROWAWAY_DIR/pwfile"
    {
        echo "listen_addresses = '127.0.0.1'"
        echo "unix_socket_directories = '$PG_THROWAWAY_DIR'"
        echo "fsync = off"
        echo "synchronous_commit = off"
        echo "full_page_writes = off"
        echo "log_min_messages = warning"
        [ -n "${PG_THROWAWAY_CONF:-}" ] && printf '%s\n' "$PG_THROWAWAY_CONF"
    } | _pgt_as sh -c 'cat >>"$1"' sh "$PG_THROWAWAY_DIR/data/postgresql.conf"
    # A port: the one asked for, else random ones until the server binds one.
    _pgt_try=0
    while :; do
        if [ -n "${PG_THROWAWAY_PORT:-}" ]; then
            _pgt_port=$PG_THROWAWAY_PORT
        else
            _pgt_port=$((20000 + $(_pgt_random) % 40000))
        fi
        if _pgt_as "$_PGT_BIN/pg_ctl" -D "$PG_THROWAWAY_DIR/data" -l "$PG_THROWAWAY_DIR/server.log" \
            -o "-p $_pgt_port" -w -t 60 start >/dev/null 2>&1; then
            break
        fi
        _pgt_try=$((_pgt_try + 1))
        if [ -n "${PG_THROWAWAY_PORT:-}" ] || [ "$_pgt_try" -ge 10 ] ||
            ! grep -q 'could not bind\|could not create any TCP/IP sockets\|Address already in use' \
                "$PG_THROWAWAY_DIR/server.log" 2>/dev/null; then
            _pgt_say "server did not start; its log:"
            cat "$PG_THROWAWAY_DIR/server.log" >&2 2>/dev/null
            pg_throwaway_stop
            return 1
        fi
    done
    export PG_THROWAWAY_BINDIR="$_PGT_BIN"
    export PGHOST="$PG_THROWAWAY_DIR" PGPORT="$_pgt_port" PGUSER="$_pgt_dbuser"
    export PGPASSWORD="$_pgt_password" PGDATABASE="${PG_THROWAWAY_DB:-nrgdb}"
    export DATABASE_URL="postgresql://$PGUSER:$PGPASSWORD@127.0.0.1:$PGPORT/$PGDATABASE"
    if ! "$_PGT_BIN/createdb" "$PGDATABASE" 2>/dev/null && ! psql -d postgres -qAtc \
        "create database \"$PGDATABASE\"" >/dev/null; then
        _pgt_say "could not create database $PGDATABASE"
        pg_throwaway_stop
        return 1
    fi
}

pg_throwaway_stop() {
    if [ -n "${PG_THROWAWAY_DIR:-}" ] && [ -d "$PG_THROWAWAY_DIR" ]; then
        if [ -f "$PG_THROWAWAY_DIR/data/postmaster.pid" ]; then
            _pgt_as "$_PGT_BIN/pg_ctl" -D "$PG_THROWAWAY_DIR/data" -m fast -w -t 60 stop \
                >/dev/null 2>&1 || _pgt_say "pg_ctl stop failed"
        fi
        rm -rf "$PG_THROWAWAY_DIR"
    fi
    unset PG_THROWAWAY_DIR PGHOST PGPORT PGUSER PGPASSWORD PGDATABASE DATABASE_URL
}

# Executed (not sourced) with `run`: start, run the command, stop.
_pgt_main() {
    case "${1:-}" in
    run)
        shift
        [ $# -gt 0 ] || { _pgt_say "usage: pg-throwaway.sh run CMD [ARGS...]"; return 2; }
        pg_throwaway_start || return 1
        _pgt_say "DATABASE_URL=$DATABASE_URL (socket folder $PGHOST)"
        _pgt_status=0
        "$@" || _pgt_status=$?
        return "$_pgt_status"
        ;;
    *)
        sed -n '2,/^$/s/^# \{0,1\}//p' "$0" >&2
        return 2
        ;;
    esac
}

case "${0##*/}" in
pg-throwaway.sh) _pgt_main "$@"; exit $? ;;
esac
