#!/usr/bin/env bash
# Re-fetches the vendored chart library of the report page (third_party/chartjs/) from the
# npm registry: exactly chart.js@VERSION, checked against the registry's recorded
# integrity (SHA-512 of the package), then its minified UMD build and its licence are
# copied in. Needs npm (and network); the build and the tests do not.
# Usage: scripts/vendor-chart-lib.sh
set -euo pipefail
VERSION=4.6.1
INTEGRITY='sha512-hJyniucsFmq//EvXYvJ6c6mahPoI3kaxdjVH8awTaJ/fDNWeSqqqArixMJWkWNN6fcYvPU3HneSANFNYtRi61g=='
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dest=$root/third_party/chartjs
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

command -v npm >/dev/null || { echo "vendor-chart-lib: npm is needed (Debian package npm)" >&2; exit 1; }
(cd "$work" && npm pack --silent "chart.js@$VERSION" >/dev/null)
tgz=$work/chart.js-$VERSION.tgz
got="sha512-$(node -e 'process.stdout.write(require("crypto").createHash("sha512")
  .update(require("fs").readFileSync(process.argv[1])).digest("base64"))' "$tgz")"
if [ "$got" != "$INTEGRITY" ]; then
  echo "vendor-chart-lib: chart.js@$VERSION integrity mismatch: $got" >&2
  exit 1
fi
tar -xzf "$tgz" -C "$work"
mkdir -p "$dest"
cp "$work/package/dist/chart.umd.min.js" "$dest/chart.umd.min.js"
cp "$work/package/LICENSE.md" "$dest/LICENSE.md"
echo "chart.js $VERSION ($INTEGRITY)" >"$dest/VERSION"
echo "vendor-chart-lib: chart.js $VERSION -> $dest"
