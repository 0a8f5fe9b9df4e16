# pack_runtime.sh (sourced by bench/assess_e2e.sh and bench/gpu_step.sh):
# pack_runtime DIR BINARY... copies into DIR/lib the shared libraries the
# binaries need that a bare device machine lacks (all but glibc's, from
# ldd), and into DIR/fonts and DIR/fonts.conf the DejaVu fonts the report
# renders with (FONTCONFIG_FILE=DIR/fonts.conf there).
pack_runtime() {
  local d=$1; shift
  mkdir -p "$d/lib" "$d/fonts"
  for f in "$@"; do ldd "$f"; done | awk '$3 ~ /^\// {print $3}' | sort -u |
    grep -v -E '/(libc|libm|libdl|libpthread|librt|libresolv|ld-linux-x86-64)\.so' |
    xargs -I{} cp -L {} "$d/lib/"
  cp /usr/share/fonts/truetype/dejavu/DejaVuSans{,-Bold,Mono}.ttf "$d/fonts/"
  cat >"$d/fonts.conf" <<'XML'
<?xml version="1.0"?>
<!DOCTYPE fontconfig SYSTEM "fonts.dtd">
<fontconfig>
  <dir prefix="relative">fonts</dir>
  <cachedir>/tmp/wl-fontcache</cachedir>
</fontconfig>
XML
}
