#!/usr/bin/env bash
# The comparison table of results/paper/README.md: every number the paper states, ours beside it
# from the analysis tables (bash results/paper/make.sh analyze first). Rewrites the README's
# section between the markers "<!-- table -->" and "<!-- /table -->"; prints the table.
# difference in SE = (ours - paper) / sqrt(SE_ours^2 + SE_paper^2); verdict: |d| < 2 agrees,
# 2 <= |d| < 5 differs, >= 5 disagrees; "not run" where the campaign has no data yet. Fig. 5's
# statements about D have no number: D_chord (the phase diagrams' order parameter) below 0.1
# counts as vanishing.
# Also rewrites the section between "<!-- curves -->" and "<!-- /curves -->": Fig. 5's curves
# point by point (seeds, the literal D, D_chord and D_kappa, mean ± SE over the seeds, from
# FIG/analysis/D_vs_<param>.csv) and each figure's critical point (FIG/analysis/critical.csv).
# PAPER_DIR: another campaign folder of the same figures (results/paper_inertial).
set -euo pipefail
here=${PAPER_DIR:-$(cd "$(dirname "$0")" && pwd)}

# value MU_S NAME FILE: "value stderr" of the row with mu_s = MU_S and column `name` (exponents)
# or `quantity` (distributions) = NAME; for distributions NAME is quantity:mu or quantity:sigma.
lookup() {
  local mu=$1 name=$2 file=$3
  [ -f "$file" ] || { echo "nan nan"; return; }
  awk -F, -v mu="$mu" -v want="$name" '
    NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    {
      if ($c["mu_s"] + 0 != mu + 0) next
      if ("name" in c) {
        if ($c["name"] == want) { print $c["value"], $c["stderr"]; found = 1; exit }
      } else {
        split(want, q, ":")
        if ($c["quantity"] == q[1] && $c["ok"] == "true") {
          se = (q[2] "_stderr") in c ? $c[q[2] "_stderr"] : "nan"
          print $c[q[2]], se; found = 1; exit
        }
      }
    }
    END { if (!found) print "nan nan" }' "$file"
}

row() {  # LABEL PAPER PAPER_SE "VALUE SE"
  local label=$1 paper=$2 pse=$3 ours=$4
  awk -v label="$label" -v p="$paper" -v ps="$pse" -v o="$ours" 'BEGIN {
    split(o, v, " ")
    if (v[1] == "nan" || v[1] == "") {
      printf "| %s | %s%s | not run | | not run |\n", label, p, (ps == "" ? "" : " ± " ps); exit
    }
    se2 = (v[2] == "nan" ? 0 : v[2] * v[2]) + (ps == "" ? 0 : ps * ps)
    d = se2 > 0 ? (v[1] - p) / sqrt(se2) : 0
    a = d < 0 ? -d : d
    verdict = se2 == 0 ? "no error bar" : (a < 2 ? "agrees" : (a < 5 ? "differs" : "disagrees"))
    printf "| %s | %s%s | %.3f ± %.3f | %.1f | %s |\n", label, p, (ps == "" ? "" : " ± " ps),
      v[1], (v[2] == "nan" ? 0 : v[2]), d, verdict
  }'
}

# order MU_KEY VALUE FILE: "mean sem" of D_chord at the row of D_vs_<param>.csv FILE whose first
# column (mu_s or eps) is VALUE.
order() {
  local file=$3
  [ -f "$file" ] || { echo "nan nan"; return; }
  awk -F, -v key="$1" -v x="$2" '
    NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $c[key] + 0 == x + 0 && $c["n"] > 0 { print $c["D_chord_mean"], $c["D_chord_sem"]; found = 1 }
    END { if (!found) print "nan nan" }' "$file"
}

# claim LABEL PAPER "MEAN SEM" WANT: the paper's statement about D (no number: "vanishes" or
# "> 0") against our mean; D counts as vanishing below 0.1 (the coil's floor over l in [5, 50]:
# the entry transient and snap-throughs, 0.05-0.08 in Fig. 5b's coiled runs).
claim() {
  awk -v label="$1" -v p="$2" -v o="$3" -v want="$4" 'BEGIN {
    split(o, v, " ")
    if (v[1] == "nan" || v[1] == "") { printf "| %s | %s | not run | | not run |\n", label, p; exit }
    ok = want == "vanishes" ? v[1] < 0.1 : v[1] >= 0.1
    printf "| %s | %s | %.3f ± %.3f | | %s |\n", label, p, v[1], v[2], ok ? "agrees" : "disagrees"
  }'
}

ex=$here/fig4/analysis/exponents.csv
di=$here/fig4/analysis/distributions.csv
table=$(
  echo "| quantity (paper's figure) | paper | wirepack mean ± SE | difference in SE | verdict |"
  echo "| --- | --- | --- | --- | --- |"
  row "α, R_t ~ l^α, coil μs = 0 (Fig. 4a)" 0.04 0.01 "$(lookup 0 alpha "$ex")"
  row "β, R_x ~ l^β, coil (Fig. 4a)" 0.35 0.01 "$(lookup 0 beta "$ex")"
  row "γ, R_y ~ l^γ, coil (Fig. 4a)" 0.46 0.01 "$(lookup 0 gamma "$ex")"
  row "N ~ l in the coil (text: exponent 1)" 1 "" "$(lookup 0 tau "$ex")"
  row "δ, Û_b ~ l^δ, crumpled μs = 1/2 (Fig. 4c)" 1.192 0.006 "$(lookup 0.5 delta "$ex")"
  row "λ, K ~ l^λ, crumpled (Fig. 4d)" 1.083 0.004 "$(lookup 0.5 lambda "$ex")"
  row "τ, N ~ l^τ, crumpled (Fig. 4b)" 1.40 0.01 "$(lookup 0.5 tau "$ex")"
  row "mean of ln(κ²/⟨κ²⟩), crumpled (Fig. 6a)" -0.29 "" "$(lookup 0.5 kappa2:mu "$di")"
  row "σ of ln(κ²/⟨κ²⟩) (Fig. 6a)" 0.83 "" "$(lookup 0.5 kappa2:sigma "$di")"
  row "mean of ln(Λ/r), crumpled (Fig. 6b)" 3.0 "" "$(lookup 0.5 Lambda_over_r:mu "$di")"
  row "σ of ln(Λ/r) (Fig. 6b)" 0.48 "" "$(lookup 0.5 Lambda_over_r:sigma "$di")"
  row "mean of ln(κ²/⟨κ²⟩), least squares to the histogram" -0.29 "" "$(lookup 0.5 kappa2:mu_ls "$di")"
  row "σ of ln(κ²/⟨κ²⟩), least squares" 0.83 "" "$(lookup 0.5 kappa2:sigma_ls "$di")"
  row "mean of ln(Λ/r), least squares" 3.0 "" "$(lookup 0.5 Lambda_over_r:mu_ls "$di")"
  row "σ of ln(Λ/r), least squares" 0.48 "" "$(lookup 0.5 Lambda_over_r:sigma_ls "$di")"
  # LABEL | PAPER | AXIS | VALUE | TABLE | WANT, one statement of Fig. 5 per line.
  while IFS='|' read -r label paper axis x file want; do
    claim "$label" "$paper" "$(order "$axis" "$x" "$here/$file")" "$want"
  done << 'ROWS'
D_chord, coil at low friction, μs = 0 (Fig. 5b)|vanishes|mu_s|0|fig5b/analysis/D_vs_mu_s.csv|vanishes
D_chord, μs = 0.2 (Fig. 5b, below the transition)|vanishes|mu_s|0.2|fig5b/analysis/D_vs_mu_s.csv|vanishes
D_chord, μs = 0.5 (Fig. 5b, the crumpled side)|> 0|mu_s|0.5|fig5b/analysis/D_vs_mu_s.csv|positive
D_chord, μs = 1 (Fig. 5b; abstract: disordered at high friction)|> 0|mu_s|1|fig5b/analysis/D_vs_mu_s.csv|positive
D_chord, stiff shell at strong friction, ε = 1, μs = 1 (Fig. 5a)|vanishes|eps|1|fig5a/analysis/D_vs_eps.csv|vanishes
D_chord, soft shell, ε = 10⁴, μs = 1 (Fig. 5a)|> 0|eps|10000|fig5a/analysis/D_vs_eps.csv|positive
ROWS
)
# curve FIG PARAM SYMBOL CRITICAL TITLE: the markdown table of FIG/analysis/D_vs_PARAM.csv (one row per
# grid point: seeds, D, D_chord, D_kappa as mean ± SE, 3 decimals) and a line with the critical
# point of FIG/analysis/critical.csv (x_c, its bootstrap interval, the model AIC prefers and
# the four AICs); nothing if the figure has no table yet.
curve() {
  local fig=$1 param=$2 sym=$3 xc=$4 title=$5
  local csv=$here/$fig/analysis/D_vs_$param.csv crit=$here/$fig/analysis/critical.csv
  [ -f "$csv" ] || return 0
  echo "**$title** (\`$fig/analysis/D_vs_$param.csv\`; the order parameter D_chord):"
  echo
  echo "| $sym | seeds | D (literal) | D_chord | D_κ |"
  echo "| --- | --- | --- | --- | --- |"
  awk -F, '
    NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    function pm(m, s) { return $c[m] == "nan" || $c[m] == "" ? "–" : sprintf("%.3f ± %.3f", $c[m], $c[s]) }
    { printf "| %s | %d | %s | %s | %s |\n", $1, $c["n"], pm("D_mean", "D_sem"),
        pm("D_chord_mean", "D_chord_sem"), pm("D_kappa_mean", "D_kappa_sem") }' "$csv"
  [ -f "$crit" ] || return 0
  echo
  awk -F, -v xc="$xc" '
    NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $c["status"] != "ok" { printf "Critical point: %s (%s).\n", $c["status"], $c["note"]; next }
    {
      f = $c["scale"] == "log10" ? "%.3g" : "%.3f"  # grid values of a log axis: 30, not 30.000
      printf "Critical point (`critical.csv`): %s = " f " [" f ", " f "], %s model (AIC: continuous %.1f, smooth %.1f, constant %.1f, line %.1f; the interval from %d bootstrap resamples of the seeds); %d runs, %d failed, %d missing.\n",
        xc, $c["x_c"], $c["x_c_lo"], $c["x_c_hi"], $c["model"], $c["aic_continuous"],
        $c["aic_smooth"], $c["aic_constant"], $c["aic_line"], $c["resamples"], $c["values"],
        $c["n_failed"], $c["n_missing"] }' "$crit"
}
curves=$(
  curve fig5b mu_s μs μc "Fig. 5b: D(μs) at ρ = 20, ξ = 10, ε = 10³, maximised over l ∈ [5, 50]"
  echo
  curve fig5a eps ε ε_c "Fig. 5a: D(ε) at ρ = 20, ξ = 30, μs = 1, maximised over l ∈ [5, 50]"
)
echo "$table"
echo
echo "$curves"
readme=$here/README.md
awk -v table="$table" -v curves="$curves" '
  /<!-- table -->/ { print; print table; skip = 1; next }
  /<!-- \/table -->/ { skip = 0 }
  /<!-- curves -->/ { print; print curves; skip = 1; next }
  /<!-- \/curves -->/ { skip = 0 }
  !skip' "$readme" > "$readme.part"
mv "$readme.part" "$readme"
