#!/usr/bin/env bash
# Layering check of the kontakt crates (issue 10, item 6). Run from .ci/run; needs only
# bash, grep and awk.
#
# It builds the import graph between the top-level modules of crates/kontakt/src (a file
# `x.rs` or a directory `x/` is module `x`) from the `crate::<module>` paths in code
# (`use crate::a::B`, `crate::a::f()`, `use crate::{a::B, b}`; comments, and so intra-doc
# links, are ignored) and checks the rules listed in RULES:
#
#   case-layer     no physics module imports the case layer (`crate::io`, which is moving
#                  to its own crate `kontakt-case`; `kontakt_case::` counts too), and
#                  crates/kontakt/Cargo.toml does not depend on kontakt-case
#   halfspace-pimp halfspace (the reference solver) does not import pimp (the method it checks)
#   layer-order    a module imports only modules of its own layer or lower ones (LAYERS)
#   no-cycles      the import graph of the top-level modules has no cycle
#
# A rule listed in EXPECTED_VIOLATIONS is still run and its findings printed, but they do
# not fail the check; once such a rule passes, the check fails until the entry is removed,
# so an exemption cannot outlive the violation.
#
# The other crates (kontakt-case, kontakt-cli) have no layer table: only no-cycles is run, on
# a graph whose nodes are files rather than top-level modules (`commands/friction.rs` is
# `commands/friction`), so a cycle between sibling submodules is found too (the CLI's
# commands/friction and commands/pimp imported each other until issue 30, item 21).
#
# Usage: tools/check-layering.sh [path/to/crate]   (default crates/kontakt; exit 0: clean, 1: violation)
set -euo pipefail
cd "$(dirname "$0")/.."
CRATE=${1:-crates/kontakt}
SRC=$CRATE/src

RULES=(case-layer halfspace-pimp layer-order no-cycles)
# Other crates of the workspace (kontakt-case, kontakt-cli) have no layer table: only cycles
# are refused.
if [[ $CRATE != crates/kontakt ]]; then
  RULES=(no-cycles)
fi

# None today: the half-space solver takes PimP's zone estimate as a parameter
# (Bem::with_estimate), so it no longer imports pimp.
EXPECTED_VIOLATIONS=()

# The allowed direction, lowest layer first; modules on one line form one layer and may
# import each other (cycles are still refused by no-cycles). A module may import only its
# own layer and lower ones. The case layer is the separate crate kontakt-case.
LAYERS=(
  "units error load solve quadrature"
  "material"
  "geometry"
  "gap"
  "field"
  "hertz"
  "pimp halfspace"
  "tangential traction lubrication rough impact gear rolling"
  "friction"
  "bearing element"
)
CASE_LAYER=kontakt_case

if [[ ! -d $SRC ]]; then
  echo "check-layering: no source tree at $SRC" >&2
  exit 2
fi

# --- the modules ----------------------------------------------------------------------------
# GRAIN=top (crates/kontakt): a module is a top-level file `x.rs` or directory `x/`.
# GRAIN=file (the other crates): every file is a module, `a/b.rs` is `a/b` and `a/mod.rs` is
# `a`, so sibling submodules (the CLI's commands/friction and commands/pimp) are nodes of
# their own; an import between a module and its own ancestor (a parent re-exporting its
# children, a child using its parent's helpers) is not an edge.
GRAIN=top
[[ $CRATE != crates/kontakt ]] && GRAIN=file
files=$(find "$SRC" -name '*.rs' ! -path "$SRC/lib.rs" ! -path "$SRC/main.rs" | LC_ALL=C sort)
module_of() {
  local rel=${1#"$SRC"/}
  if [[ $GRAIN == top ]]; then
    rel=${rel%%/*}
    echo "${rel%.rs}"
  else
    rel=${rel%.rs}
    echo "${rel%/mod}"
  fi
}
modules=$(for f in $files; do module_of "$f"; done | LC_ALL=C sort -u)

# --- the import graph: lines "from to file:line" -------------------------------------------
# The awk prints each `crate::a::b::c` path (and, at file grain, each unindented
# `use super::a::b`, resolved against the file's parent) as a/b/c; `resolve` then maps it to
# the longest known module prefix (at top grain: its first segment).
raw_edges=$(
  for f in $files; do
    mod=$(module_of "$f")
    # `super` of module a/b (a/b.rs or a/b/mod.rs) is a; of a top-level module, the root
    parent=${mod%/*}
    [[ $parent == "$mod" ]] && parent=""
    awk -v mod="$mod" -v file="$f" -v grain="$GRAIN" -v parent="$parent" '
      function path(s,   m) {          # the leading module path of s, as a/b/c
        if (match(s, /^[ \t\n]*[a-z_][a-z0-9_]*([ \t\n]*::[ \t\n]*[a-z_][a-z0-9_]*)*/)) {
          m = substr(s, RSTART, RLENGTH); gsub(/[ \t\n]/, "", m); gsub(/::/, "/", m); return m
        }
        return ""
      }
      function emit(to, at) { if (to != "" && to != "self" && to != "super") print mod, to, file ":" at }
      {
        line = $0
        # strip comments (doc comments included); a "//" inside a string literal is rare
        # enough in these crates not to matter
        if (in_block) { if (sub(/.*\*\//, "", line)) in_block = 0; else next }
        gsub(/\/\*.*\*\//, "", line)
        if (sub(/\/\*.*/, "", line)) in_block = 1
        sub(/\/\/.*/, "", line)
        if (grain == "file" && match(line, /^use[ \t]+super::/)) {   # a file-level `use super::`
          rest = substr(line, RSTART + RLENGTH)
          if (match(rest, /^([a-z_][a-z0-9_]*::)*\{/)) {              # super::{a, b::C} or super::x::{...}
            pre = substr(rest, 1, RLENGTH - 1); gsub(/::/, "/", pre)
            rest = substr(rest, RLENGTH + 1); d = 0; item = ""
            for (i = 1; i <= length(rest); i++) {
              c = substr(rest, i, 1)
              if (c == "{") d++
              if (c == "}" && d-- == 0) { emit(parent (parent == "" ? "" : "/") pre path(item), NR); break }
              if (c == "," && d == 0) { emit(parent (parent == "" ? "" : "/") pre path(item), NR); item = ""; continue }
              item = item c
            }
          } else emit(parent (parent == "" ? "" : "/") path(rest), NR)
          next
        }
        if (group != "") {                  # inside a multi-line `crate::{ ... }`
          group = group " " line; line = ""
        } else if (match(line, /crate::([a-z_][a-z0-9_]*::)*\{/)) {
          prefix = substr(line, RSTART + 7, RLENGTH - 8); gsub(/::/, "/", prefix)
          group = substr(line, RSTART + RLENGTH - 1); start = NR
          line = substr(line, 1, RSTART - 1)
        }
        if (group != "") {
          opened = gsub(/\{/, "{", group); closed = gsub(/\}/, "}", group)
          if (closed < opened) next           # the group goes on on the next line
          depth = 0; item = ""
          for (i = 1; i <= length(group); i++) {
            c = substr(group, i, 1)
            if (c == "{") { depth++; if (depth == 1) { item = ""; continue } }
            if (c == "}") { depth--; if (depth == 0) { emit(prefix path(item), start); break } }
            if (c == "," && depth == 1) { emit(prefix path(item), start); item = ""; continue }
            item = item c
          }
          line = line " " substr(group, i + 1); group = ""
        }
        while (match(line, /(^|[^a-zA-Z0-9_])crate::[a-z_][a-z0-9_]*(::[a-z_][a-z0-9_]*)*/)) {
          seg = substr(line, RSTART, RLENGTH); sub(/.*crate::/, "", seg); gsub(/::/, "/", seg)
          emit(seg, NR)
          line = substr(line, RSTART + RLENGTH)
        }
      }
      /kontakt_case::/ && !/^[ \t]*\/\// { print mod, "kontakt_case", file ":" NR }
    ' "$f"
  done
)
# Resolve each path to a module and drop self-imports (and, at file grain, imports between
# a module and its ancestor).
edges=$(awk -v grain="$GRAIN" -v mods="$modules" '
  BEGIN { n = split(mods, m, /[ \n]+/); for (i = 1; i <= n; i++) known[m[i]] }
  function ancestor(a, b) { return index(b "/", a "/") == 1 }
  NF >= 3 {
    to = $2
    if (grain == "top" || to == "kontakt_case") { sub(/\/.*/, "", to) }
    else {
      while (!(to in known) && index(to, "/")) sub(/\/[^\/]*$/, "", to)
      if (!(to in known)) next          # an item of the crate root (main.rs, lib.rs)
    }
    if (to == $1) next
    if (grain == "file" && (ancestor(to, $1) || ancestor($1, to))) next
    print $1, to, $3
  }' <<<"$raw_edges")

# --- report the graph ---------------------------------------------------------------------
echo "check-layering: module imports in $SRC (code only, comments ignored)"
width=$(awk '{ if (length($0) > w) w = length($0) } END { print w }' <<<"$modules")
for m in $modules; do
  deps=$(awk -v m="$m" '$1 == m { print $2 }' <<<"$edges" | LC_ALL=C sort -u | tr '\n' ' ')
  printf '  %-*s -> %s\n' "$width" "$m" "${deps:-(nothing)}"
done

# --- the rules: each prints its violations, one per line, and nothing when it holds -------
rule_case-layer() {
  awk -v c="$CASE_LAYER" '$1 != c && ($2 == c || $2 == "kontakt_case") {
    printf "%s imports the case layer (%s) at %s: physics must not depend on case files\n", $1, $2, $3
  }' <<<"$edges"
  if grep -v '^[[:space:]]*#' "$CRATE/Cargo.toml" | grep -q 'kontakt-case'; then
    echo "$CRATE/Cargo.toml depends on kontakt-case: the case layer depends on the library, not the reverse"
  fi
}

rule_halfspace-pimp() {
  awk '$1 == "halfspace" && $2 == "pimp" {
    printf "halfspace imports pimp at %s: the reference solver must not depend on the method it checks\n", $3
  }' <<<"$edges"
}

rule_layer-order() {
  local layers_flat="" i=0 l
  for l in "${LAYERS[@]}"; do
    for m in $l; do layers_flat+="$m=$i "; done
    i=$((i + 1))
  done
  local m
  for m in $modules; do
    [[ " $layers_flat" == *" $m="* ]] ||
      echo "module $m is not in LAYERS of tools/check-layering.sh: add it to its layer"
  done
  awk -v spec="$layers_flat" 'BEGIN { n = split(spec, a, " "); for (i = 1; i <= n; i++) { split(a[i], kv, "="); rank[kv[1]] = kv[2] } }
    ($1 in rank) && ($2 in rank) && rank[$2] > rank[$1] {
      printf "%s (layer %d) imports %s (layer %d) at %s: lower layers may not import higher ones\n", $1, rank[$1], $2, rank[$2], $3
    }' <<<"$edges"
}

rule_no-cycles() {
  awk '
    { if (!(($1, $2) in seen)) { seen[$1, $2] = 1; adj[$1] = adj[$1] " " $2 }; nodes[$1]; nodes[$2] }
    function dfs(u, path,   n, vs, i, v) {
      state[u] = 1
      n = split(adj[u], vs, " ")
      for (i = 1; i <= n; i++) {
        v = vs[i]
        if (state[v] == 1) {            # back edge: report the cycle once
          cyc = substr(path, index(path " ", " " v " ") + 1) " " v
          sub(/^ +/, "", cyc)
          if (!(cyc in reported)) { reported[cyc]; gsub(/ /, " -> ", cyc); print "import cycle: " cyc }
        } else if (state[v] == 0) dfs(v, path " " v)
      }
      state[u] = 2
    }
    END { for (u in nodes) state[u] = 0; for (u in nodes) if (state[u] == 0) dfs(u, " " u) }
  ' <<<"$edges" | LC_ALL=C sort
}

# --- run ----------------------------------------------------------------------------------
status=0
for rule in "${RULES[@]}"; do
  found=$("rule_$rule")
  expected=0
  for e in "${EXPECTED_VIOLATIONS[@]}"; do [[ $e == "$rule" ]] && expected=1; done
  if [[ -z $found ]]; then
    if ((expected)); then
      echo "FAIL  $rule: passes now, but is listed in EXPECTED_VIOLATIONS; remove it there (tools/check-layering.sh)"
      status=1
    else
      echo "ok    $rule"
    fi
  elif ((expected)); then
    echo "KNOWN $rule (expected violation, TODO issue 10; does not fail the check):"
    sed 's/^/        /' <<<"$found"
  else
    echo "FAIL  $rule:"
    sed 's/^/        /' <<<"$found"
    status=1
  fi
done
if ((status)); then
  echo "check-layering: FAILED (see docs in tools/check-layering.sh)" >&2
else
  echo "check-layering: OK"
fi
exit $status
