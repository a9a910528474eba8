# SPDX-License-Identifier: BSL-1.0
# The flash and stack of a function and everything it calls in one object file, from GCC's call graph
# (-fcallgraph-info=su writes OBJECT.ci: a node per function with its frame size, an edge per call) and the
# object's symbol sizes (arm-none-eabi-nm -S). For every function whose name matches the regular expression
# `roots`, prints one line: its name, the bytes of text of the functions reachable from it in this object
# (each counted once), the deepest stack on a call path from it (the sum of the frames), and the functions
# called outside the object ("-" if none). Used by scripts/audit.sh (the steppers' flash and stack) and
# scripts/bench-m4f.sh (odestep's step against the hand loops).
#
#   awk -v sizes_cmd="arm-none-eabi-nm -S OBJECT" -v roots='^audit_step_' -f scripts/callgraph.awk OBJECT.ci
BEGIN {
  while ((sizes_cmd | getline line) > 0) {
    n = split(line, field, " ")
    if (n == 4) size[field[4]] = strtonum_hex(field[2])
  }
}
function strtonum_hex(h,    i, c, v) {
  v = 0
  for (i = 1; i <= length(h); i++) { c = index("0123456789abcdef", tolower(substr(h, i, 1))) - 1; v = v * 16 + c }
  return v
}
function title(s) { sub(/^title: "/, "", s); sub(/".*/, "", s); sub(/^[^:]*\.cpp:/, "", s); return s }
/^node:/ {
  match($0, /title: "[^"]*"/); name = title(substr($0, RSTART, RLENGTH))
  if (match($0, /[0-9]+ bytes/)) frame[name] = substr($0, RSTART, RLENGTH) + 0
  else external[name] = 1
  nodes[name] = 1
}
/^edge:/ {
  match($0, /sourcename: "[^"]*"/); s = substr($0, RSTART, RLENGTH); sub(/^sourcename/, "title", s); s = title(s)
  match($0, /targetname: "[^"]*"/); t = substr($0, RSTART, RLENGTH); sub(/^targetname/, "title", t); t = title(t)
  if (!((s, t) in edge)) { edge[s, t] = 1; callees[s] = callees[s] " " t }
}
function deepest(f,    n, list, i, d, best) {  # largest sum of frames on a call path from f
  if (f in memo) return memo[f]
  best = 0
  n = split(callees[f], list, " ")
  for (i = 1; i <= n; i++) if (!(list[i] in external)) { d = deepest(list[i]); if (d > best) best = d }
  memo[f] = frame[f] + best
  return memo[f]
}
function reach(f,    n, list, i) {
  if (f in seen) return
  seen[f] = 1
  if (f in external) { helpers[f] = 1; return }
  text += size[f]
  n = split(callees[f], list, " ")
  for (i = 1; i <= n; i++) reach(list[i])
}
END {
  for (wrapper in nodes) {
    if (wrapper !~ roots) continue
    delete seen; delete helpers; text = 0
    reach(wrapper)
    h = ""
    for (x in helpers) h = h (h == "" ? "" : ",") x
    print wrapper, text, deepest(wrapper), (h == "" ? "-" : h)
  }
}
