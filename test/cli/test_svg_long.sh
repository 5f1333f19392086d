# --format svg of a long run (20001 steps of PR 3207): every curve drawn through at most 4096
# of its points, keeping its extremes (tools/svg_check.py hodographs: each drawn point is a
# step's force, in order, and in each of the 1024 buckets of steps the bucket's largest and
# smallest components are drawn: every peak survives); valid XML, a small file; the numbers
# (legend, CSV) are those of the full run.
long_n=20001
long_d=$(run_py -c "print(360 / ($long_n - 1))")
run_ks data/pr3207.nml --set dphi="$long_d" --set n=$long_n --format svg --quiet; cp "$out" "$cli_tmp/long.svg"
run_ks data/pr3207.nml --set dphi="$long_d" --set n=$long_n --format csv --quiet; cp "$out" "$cli_tmp/long.csv"
run_py tools/svg_check.py hodographs "$cli_tmp/long.svg" "$cli_tmp/long.csv" >"$cli_tmp/long_check.txt" 2>&1 \
  && pass || fail svg-long-hodographs "$(cat "$cli_tmp/long_check.txt")"
xmllint --noout "$cli_tmp/long.svg" 2>"$cli_tmp/long_xml.txt" && pass || fail svg-long-xml "$(head -3 "$cli_tmp/long_xml.txt")"
run_py - "$cli_tmp/long.svg" <<'PY' && pass || fail svg-long-size "a path has more than 4096 points or the file is large"
import os, re, sys
text = open(sys.argv[1]).read()
most = max(len(re.findall(r"[ML] ", d)) for d in re.findall(r' d="([^"]*)"', text))
size = os.path.getsize(sys.argv[1])
# 20001 steps drawn in full were 11 MB (rays, dots, 10^4-point paths); thinned ~400 KB
if most > 4096 or size > 1_000_000 or "of 20001 points drawn" not in text:
    print(f"largest path {most} points, file {size} bytes"); sys.exit(1)
PY
