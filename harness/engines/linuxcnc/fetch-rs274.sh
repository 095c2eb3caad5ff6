#!/usr/bin/env bash
# Fetches LinuxCNC's stand-alone G-code interpreter `rs274` from Debian's `linuxcnc-uspace` package
# without installing it (a full install pulls a real-time kernel): `apt-get download` the .deb files
# and `dpkg -x` them into BUILD_DIR/linuxcnc/. Besides the package itself it fetches the shared
# libraries rs274 links that this machine does not have (as `ldd` reports them), e.g.
# libboost-python1.74.0, libpython3.11, libedit2, libtirpc3.
#
#   harness/engines/linuxcnc/fetch-rs274.sh BUILD_DIR
#
# Idempotent: does nothing when rs274 is already there and runs. Prints where rs274 is on its last
# line ("rs274: PATH"). Exits 1 with a message when the archive cannot be reached or a library has
# no known package, 2 on bad usage. The engine (harness/engines/linuxcnc/linuxcnc_engine.cpp) runs
# BUILD_DIR/linuxcnc/usr/bin/rs274 with LD_LIBRARY_PATH set to the library folders below, which is
# what the wrapper BUILD_DIR/linuxcnc/rs274 written here does too.
set -euo pipefail

die() { echo "fetch-rs274: $*" >&2; exit 1; }

if [[ $# -ne 1 || "$1" == -h || "$1" == --help ]]; then
  echo "usage: $0 BUILD_DIR   (extracts rs274 into BUILD_DIR/linuxcnc/)" >&2
  exit 2
fi

build_dir=$1
mkdir -p "$build_dir"
build_dir=$(cd "$build_dir" && pwd)
dest=$build_dir/linuxcnc
debs=$build_dir/linuxcnc-debs
rs274=$dest/usr/bin/rs274
package=linuxcnc-uspace

# The shared library folders of an extracted tree, ':'-separated.
library_path() {
  local root=$1 dirs=() d
  for d in "$root/usr/lib" "$root"/usr/lib/*-linux-gnu* "$root"/lib/*-linux-gnu*; do
    [[ -d $d ]] && dirs+=("$d")
  done
  local IFS=:
  echo "${dirs[*]}"
}

# rs274 starts an embedded Python 3.11. When this script had to fetch libpython3.11 (and with it
# libpython3.11-minimal, the core modules), Python must find its modules in the extracted tree.
python_home() {
  local root=$1
  [[ -d $root/usr/lib/python3.11/encodings ]] && echo "$root/usr"
  return 0
}

# Sonames ldd cannot resolve for rs274 under the extracted tree.
missing_sonames() {
  local root=$1
  LD_LIBRARY_PATH=$(library_path "$root") ldd "$root/usr/bin/rs274" 2>/dev/null |
    awk '/=> not found/ { print $1 }' | sort -u
}

# Runs rs274 on a two-line program in a private HOME: proves the extracted tree works.
smoke_test() {
  local root=$1 tmp out
  tmp=$(mktemp -d)
  : >"$tmp/tool.tbl"
  printf 'G18 G21 G90\nG0 X1 Z1\nM2\n' >"$tmp/smoke.ngc"
  local pyhome
  pyhome=$(python_home "$root")
  out=$(cd "$tmp" && HOME=$tmp LD_LIBRARY_PATH=$(library_path "$root") ${pyhome:+PYTHONHOME=$pyhome} \
    timeout 10 "$root/usr/bin/rs274" -g -t "$tmp/tool.tbl" "$tmp/smoke.ngc" 2>&1) || true
  rm -rf "$tmp"
  grep -q 'STRAIGHT_TRAVERSE(1.0000, 0.0000, 1.0000' <<<"$out"
}

if [[ -x $rs274 ]] && [[ -z $(missing_sonames "$dest") ]] && smoke_test "$dest"; then
  echo "rs274: $rs274"
  exit 0
fi

# The package that ships each library rs274 (or a library it pulls in) may need. Debian bookworm.
package_for() {
  case $1 in
    libboost_python311.so.*) echo libboost-python1.74.0 ;;
    libpython3.11.so.*) echo "libpython3.11 libpython3.11-minimal" ;;
    libedit.so.2) echo libedit2 ;;
    libtirpc.so.3) echo libtirpc3 ;;
    libbsd.so.0) echo libbsd0 ;;
    libmd.so.0) echo libmd0 ;;
    libexpat.so.1) echo libexpat1 ;;
    libz.so.1) echo zlib1g ;;
    libtinfo.so.6) echo libtinfo6 ;;
    libgssapi_krb5.so.2) echo libgssapi-krb5-2 ;;
    libkrb5.so.3) echo libkrb5-3 ;;
    libk5crypto.so.3) echo libk5crypto3 ;;
    libkrb5support.so.0) echo libkrb5support0 ;;
    libkeyutils.so.1) echo libkeyutils1 ;;
    libcom_err.so.2) echo libcom-err2 ;;
    libstdc++.so.6) echo libstdc++6 ;;
    libgcc_s.so.1) echo libgcc-s1 ;;
    *) return 1 ;;
  esac
}

command -v apt-get >/dev/null || die "apt-get is not available: rs274 comes from Debian's $package package"
command -v dpkg >/dev/null || die "dpkg is not available: rs274 comes from Debian's $package package"

exec 9>"$build_dir/.fetch-rs274.lock"
flock 9  # two builds fetching at once: the second waits, then finds everything there
if [[ -x $rs274 ]] && [[ -z $(missing_sonames "$dest") ]] && smoke_test "$dest"; then
  echo "rs274: $rs274"
  exit 0
fi

mkdir -p "$debs"
log=$debs/apt.log  # kept, with the .deb files, only when the fetch fails
: >"$log"
updated=0

# apt-get download PACKAGE…, once more after `apt-get update` (as root) when the lists lack them.
download() {
  if (cd "$debs" && apt-get download "$@" >>"$log" 2>&1); then return 0; fi
  if [[ $updated -eq 0 && $(id -u) -eq 0 ]]; then
    updated=1
    echo "fetch-rs274: apt-get download failed; running apt-get update once" >&2
    apt-get update >>"$log" 2>&1 || true
    if (cd "$debs" && apt-get download "$@" >>"$log" 2>&1); then return 0; fi
  fi
  tail -n 5 "$log" >&2
  die "cannot download $* from the Debian archive (see $log); is the archive reachable and are apt's lists current (apt-get update)?"
}

# Extract into a fresh tree and move it into place when it works, so that an interrupted run
# leaves nothing half-done.
stage=$(mktemp -d "$build_dir/linuxcnc.stage.XXXXXX")
trap 'rm -rf "$stage"' EXIT

echo "fetch-rs274: downloading $package (about 22 MB)" >&2
rm -f "$debs"/*.deb
download "$package"
dpkg -x "$debs"/${package}_*.deb "$stage"
[[ -x $stage/usr/bin/rs274 ]] || die "$package has no usr/bin/rs274"

fetched=()
for round in 1 2 3 4; do
  mapfile -t missing < <(missing_sonames "$stage")
  [[ ${#missing[@]} -eq 0 ]] && break
  wanted=()
  for so in "${missing[@]}"; do
    pkgs=$(package_for "$so") || die "rs274 needs $so, which no package known to this script provides (round $round); add it to package_for()"
    for p in $pkgs; do
      [[ " ${fetched[*]} " == *" $p "* ]] || wanted+=("$p")
    done
  done
  [[ ${#wanted[@]} -eq 0 ]] && die "rs274 still misses ${missing[*]} after extracting ${fetched[*]}"
  echo "fetch-rs274: rs274 misses ${missing[*]}: downloading ${wanted[*]}" >&2
  download "${wanted[@]}"
  for p in "${wanted[@]}"; do
    dpkg -x "$debs"/${p}_*.deb "$stage"
    fetched+=("$p")
  done
done
mapfile -t missing < <(missing_sonames "$stage")
[[ ${#missing[@]} -eq 0 ]] || die "rs274 still misses ${missing[*]}"

dpkg-deb -f "$debs"/${package}_*.deb Version >"$stage/VERSION"
libs=$(library_path "$stage")
libs=${libs//$stage/\$here}
pyhome=$(python_home "$stage")
pyhome=${pyhome:+PYTHONHOME=\$here/usr }
cat >"$stage/rs274" <<EOF
#!/bin/sh
# rs274 from $package $(cat "$stage/VERSION"), extracted by fetch-rs274.sh.
here=\$(dirname "\$0")
${pyhome}LD_LIBRARY_PATH=$libs\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH} exec "\$here/usr/bin/rs274" "\$@"
EOF
chmod +x "$stage/rs274"

smoke_test "$stage" || die "the extracted rs274 does not run (try: $stage/usr/bin/rs274 -g)"

rm -rf "$dest"
mv "$stage" "$dest"
trap - EXIT
rm -rf "$debs"
echo "fetch-rs274: $package $(cat "$dest/VERSION") extracted into $dest" >&2
echo "rs274: $rs274"
