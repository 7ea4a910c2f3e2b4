#!/usr/bin/env bash
# Installs the named Debian packages that are missing (apt-get, as root or through sudo), after
# `apt-get update`; installed ones cost nothing. Usage: scripts/install_packages.sh WHO PACKAGE...
# (WHO prefixes the log line).
set -euo pipefail
who="$1"
shift
missing=()
for p in "$@"; do
  dpkg-query -W -f='${Status}' "$p" 2> /dev/null | grep -q "install ok installed" || missing+=("$p")
done
((${#missing[@]})) || exit 0
sudo=""
[[ $(id -u) -ne 0 ]] && sudo="sudo"
echo "$who: installing ${missing[*]}"
# Wait for another apt run (an unattended upgrade) instead of failing on its lock.
apt=(apt-get -o DPkg::Lock::Timeout=600)
$sudo "${apt[@]}" update -q
DEBIAN_FRONTEND=noninteractive $sudo "${apt[@]}" install -y -q --no-install-recommends "${missing[@]}"
