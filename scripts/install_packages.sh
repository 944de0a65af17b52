#!/usr/bin/env bash
# scripts/install_packages.sh WHO PACKAGE...: installs the Debian packages of
# the list that are missing (with sudo when not run as root), so that the
# scripts that call it work as they are on a fresh Debian 12 machine; WHO
# names the caller in its message. Under a lock: CI runs two steps at a time
# (.ci/run), and two apt-get runs at once would fail on dpkg's own lock.
set -euo pipefail
who=$1
shift
missing() {
  local p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}
mapfile -t need < <(missing "$@")
((${#need[@]})) || exit 0
exec 9>"${TMPDIR:-/tmp}/b2b-install-packages.lock"
flock 9
# Another caller may have installed them while this one waited.
mapfile -t need < <(missing "${need[@]}")
((${#need[@]})) || exit 0
echo "$who: installing missing Debian packages: ${need[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo=sudo
# B2B_APT_UNSAFE_IO=1 (set by .ci/run, whose machine is discarded after the
# run): dpkg unpacks without syncing each file to disk, so a crash during
# the install could leave broken packages behind; not for a machine one keeps.
unsafe=()
[ "${B2B_APT_UNSAFE_IO:-0}" = 1 ] && unsafe=(-o Dpkg::Options::=--force-unsafe-io)
$sudo apt-get update -q
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${unsafe[@]}" \
  "${need[@]}"
