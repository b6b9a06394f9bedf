# sampler-spectrum.gp — the radially averaged power spectrum of the Cornell box's 16-spp error,
# Sobol against independent numbers (data: sampler-spectrum.csv, from tests/bench/sampler_error.sh).
#   gnuplot docs/trade/sampler-spectrum.gp     (from the repository root)
set terminal svg size 640,400 dynamic font "sans,11"
set output "docs/trade/sampler-spectrum.svg"
set datafile separator ","
set key top left
set xlabel "spatial frequency (cycles per pixel)"
set ylabel "power of the relative error"
set logscale y
set grid
set title "Cornell box 128², 16 spp, depth 8 (vkpt): error spectrum"
plot "docs/trade/sampler-spectrum.csv" skip 2 using 1:2 with lines lw 2 title "sobol (default)", \
     "" skip 2 using 1:3 with lines lw 2 title "independent"
