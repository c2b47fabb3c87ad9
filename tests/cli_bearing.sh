#!/bin/sh
# cli_bearing.sh - `holonomy tile bearing` (SPEC 8): SPEC's example, the
# '-' cases, bad lines (one stderr line, nothing printed for them), and in
# every tiling {4,4}..{4,8} random lines checked against a hyperboloid
# model written here in awk (3x3 Lorentz frames, or rigid motions in the
# flat grid; it shares nothing with core/); in {4,4} TRUE equals FLAT
# wherever FLAT is a number.
. "$(dirname "$0")/lib.sh"

printf 'NESW O\n- O\nN O\nNESW N\n  W   O  \nNNNN Nf\n' >"$T/in"
expect "examples {4,5}" 0 '0.0 -
- -
180.0 180.0
31.7 0.0
90.0 90.0
180.0 180.0
' "$H" tile bearing

printf 'NESW O\nNE O\nNE E\n- Nr\n' >"$T/in"
expect "examples {4,4}" 0 '- -
225.0 225.0
180.0 -
45.0 -
' "$H" tile bearing --tiling 4,4

# bad lines: the good lines before are printed, nothing for the bad one
for bad in 'NX O' 'N' 'N O O' 'N Nll' 'N Q' '- -' 'N nf'; do
  printf 'N O\n%s\nN O\n' "$bad" >"$T/in"
  expect "bad '$bad'" 2 '180.0 180.0
' "$H" tile bearing
  err_line "line 2"
done
printf 'N O\n%061d O\n' 0 | sed '2s/0/N/g' >"$T/in"
expect "beyond reach" 2 '180.0 180.0
' "$H" tile bearing
err_line "step 61"
printf 'N Nff\n' >"$T/in"
expect "address of another tiling" 0 '0.0 -
' "$H" tile bearing --tiling 4,6
run "help" 0 "$H" tile bearing --help
grep -q 'tile bearing' "$T/out" && ok || bad "help names tile bearing"
run "bad tiling" 2 "$H" tile bearing --tiling 4,9
err_line "tiling"

# The model: lines "WALK TARGET TRUE FLAT" (the tool's answer appended);
# prints one line per disagreement.
model='
function acosh(x) { return log(x + sqrt(x * x - 1)) }
function ident(m) { m[0]=1; m[1]=0; m[2]=0; m[3]=0; m[4]=1; m[5]=0; m[6]=0; m[7]=0; m[8]=1 }
function mul(a, b, r,   i, j) {
  for (i = 0; i < 3; i++) for (j = 0; j < 3; j++)
    r[3*i+j] = a[3*i]*b[j] + a[3*i+1]*b[3+j] + a[3*i+2]*b[6+j] }
function copy(a, r,   i) { for (i = 0; i < 9; i++) r[i] = a[i] }
# m = m * R(k) * T * R(-k): a step in direction k (quarter turns ccw)
function step(m, k,   c, s, R, Ri, A, B) {
  c = (k == 0) - (k == 2); s = (k == 1) - (k == 3)
  R[0]=c; R[1]=-s; R[2]=0; R[3]=s; R[4]=c; R[5]=0; R[6]=0; R[7]=0; R[8]=1
  Ri[0]=c; Ri[1]=s; Ri[2]=0; Ri[3]=-s; Ri[4]=c; Ri[5]=0; Ri[6]=0; Ri[7]=0; Ri[8]=1
  mul(m, R, A); mul(A, Tm, B); mul(B, Ri, A); copy(A, m) }
function same(a, b) { return (a[2]-b[2])^2 + (a[5]-b[5])^2 < 1e-12 * (1 + a[8]^2 + b[8]^2) }
function deg(e, n,   d) { d = atan2(e, n) * 180 / PI; if (d < 0) d += 360; return d }
function near(got, want,   x) {
  if (got == "-" || want == "-") return got == want
  x = got - want; if (x < 0) x = -x; if (x > 180) x = 360 - x
  return x < 0.0501 }
BEGIN {
  PI = atan2(0, -1); ident(Tm)
  if (Q == 4) Tm[5] = 1
  else { d = 2 * acosh(cos(PI / Q) / sin(PI / 4)); Tm[4] = Tm[8] = (exp(d) + exp(-d)) / 2; Tm[5] = Tm[7] = (exp(d) - exp(-d)) / 2 }
  dir["N"] = 0; dir["W"] = 1; dir["S"] = 2; dir["E"] = 3; code["f"] = 0; code["l"] = 1; code["r"] = 3
}
{
  ident(P); h = 0
  if ($2 != "O") for (i = 1; i <= length($2); i++) {
    ch = substr($2, i, 1); h = (h + (i == 1 ? dir[ch] : code[ch])) % 4; step(P, h) }
  ident(M); x = y = 0; seen = same(M, P); tx = ty = 0
  w = $1 == "-" ? "" : $1
  for (i = 1; i <= length(w); i++) {
    ch = substr(w, i, 1); step(M, dir[ch])
    x += (ch == "E") - (ch == "W"); y += (ch == "N") - (ch == "S")
    if (!seen && same(M, P)) { seen = 1; tx = x; ty = y } }
  # the target in the walk frame: solve M v = p (Cramer)
  a=M[0]; b=M[1]; c=M[2]; dd=M[3]; e=M[4]; f=M[5]; g=M[6]; hh=M[7]; k=M[8]
  det = a*(e*k-f*hh) - b*(dd*k-f*g) + c*(dd*hh-e*g)
  p0 = P[2]; p1 = P[5]; p2 = P[8]
  v0 = (p0*(e*k-f*hh) - b*(p1*k-f*p2) + c*(p1*hh-e*p2)) / det
  v1 = (a*(p1*k-f*p2) - p0*(dd*k-f*g) + c*(dd*p2-p1*g)) / det
  tr = same(M, P) ? "-" : deg(v0, v1)
  fl = (seen && (tx != x || ty != y)) ? deg(tx - x, ty - y) : "-"
  if (!near($3, tr) || !near($4, fl)) print "model: " $0 " want " tr " " fl
  if (Q == 4 && $4 != "-" && $3 != $4) print "flat grid: " $0
  n++
}
END { print n " lines" }'

for q in 4 5 6 7 8; do
  # random walks (0..7 steps) and targets: the tile of a random walk of 0..5
  # steps, or of a prefix of the walk itself
  awk -v s=$q 'BEGIN { srand(s); for (i = 0; i < 300; i++) {
      n = int(rand() * 8); w = ""; for (j = 0; j < n; j++) w = w substr("NESW", int(rand() * 4) + 1, 1)
      m = int(rand() * 6); v = ""; for (j = 0; j < m; j++) v = v substr("NESW", int(rand() * 4) + 1, 1)
      if (i % 2) v = substr(w, 1, int(rand() * (n + 1)))
      print (w == "" ? "-" : w), (v == "" ? "-" : v) } }' >"$T/wv"
  cut -d' ' -f2 "$T/wv" >"$T/in"
  "$H" tile walk --tiling 4,$q <"$T/in" | cut -d' ' -f1 >"$T/addr"
  cut -d' ' -f1 "$T/wv" | paste -d' ' - "$T/addr" >"$T/in"
  run "bearing {4,$q}" 0 sh -c "\"\$1\" tile bearing --tiling 4,$q <\"\$2\"" - "$H" "$T/in" || continue
  paste -d' ' "$T/in" "$T/out" | awk -v Q=$q "$model" >"$T/check"
  if [ "$(cat "$T/check")" = "300 lines" ]; then ok; else bad "{4,$q} against the model:"; head -5 "$T/check"; fi
  if [ $q = 4 ] && [ "$(awk '$2 != "-"' "$T/out" | wc -l)" -lt 30 ]; then bad "{4,4}: too few flat bearings"; fi
done

finish "cli_bearing"
