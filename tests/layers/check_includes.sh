#!/usr/bin/env bash
# The layers' include graph (docs/design.md §1): every #include "DIR/..." of a source file under
# a layer's directory must name that layer or one it may use:
#   core -> core;  engine -> engine, core;  analysis -> analysis, core;
#   sweep -> sweep, engine, analysis, core;  report -> report, sweep, analysis, core;
#   app -> app, sweep, report, core.
# Prints each include that breaks the graph (file:line, the layer it reaches) and exits 1 if there
# is one, 0 otherwise.
#   check_includes.sh SOURCE_DIR
#   check_includes.sh --self-test   trees with engine/ including sweep/ or core/ including engine/
#                                   must fail, a clean one pass
set -euo pipefail
check() {
  local root=$1 bad=0 layer allowed file line target
  local layers=" core engine analysis sweep report app "
  declare -A may=([core]="core" [engine]="engine core" [analysis]="analysis core"
    [sweep]="sweep engine analysis core" [report]="report sweep analysis core"
    [app]="app sweep report core")
  for layer in core engine analysis sweep report app; do
    [ -d "$root/$layer" ] || continue
    allowed=" ${may[$layer]} "
    while IFS=: read -r file line target; do
      target=${target#*\"}
      target=${target%%/*}
      [[ $layers == *" $target "* ]] || continue  # a system or third-party header
      if [[ $allowed != *" $target "* ]]; then
        echo "${file#"$root"/}:$line: $layer includes $target (allowed: ${may[$layer]})"
        bad=1
      fi
    done < <(grep -rnE '^[[:space:]]*#[[:space:]]*include[[:space:]]+"[a-z0-9_]+/' \
      --include='*.cpp' --include='*.hpp' --include='*.c' --include='*.h' "$root/$layer" || true)
  done
  return $bad
}
if [ "${1:-}" = --self-test ]; then
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  mkdir -p "$tmp/engine" "$tmp/sweep" "$tmp/report"
  printf '#include "engine/params.hpp"\n#include "analysis/stats.hpp"\n' > "$tmp/sweep/a.cpp"
  printf '#include "sweep/running/run.hpp"\n' > "$tmp/report/b.hpp"
  check "$tmp" > "$tmp/out" || { cat "$tmp/out"; echo "self-test: a clean tree failed"; exit 1; }
  printf '#include <vector>\n  #include "sweep/runfile/run_file.hpp"\n' > "$tmp/engine/c.cpp"
  if check "$tmp" > "$tmp/out"; then echo "self-test: engine -> sweep was not caught"; exit 1; fi
  grep -q '^engine/c.cpp:2: engine includes sweep' "$tmp/out" ||
    { cat "$tmp/out"; echo "self-test: wrong report"; exit 1; }
  rm "$tmp/engine/c.cpp"
  mkdir -p "$tmp/core"
  printf '#include "engine/types.hpp"\n' > "$tmp/core/d.hpp"
  if check "$tmp" > "$tmp/out"; then echo "self-test: core -> engine was not caught"; exit 1; fi
  echo "self-test: passed"
  exit 0
fi
check "${1:?usage: check_includes.sh SOURCE_DIR | --self-test}"
