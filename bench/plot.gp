# bench/plot.gp: time per call against error, polygon.lua beside the tutorial baseline. From the
# repository root, after bench/run.lua wrote the data: gnuplot [-e "out='other.png'"] bench/plot.gp
# Filled marks: LuaJIT; open marks: Lua 5.4 (its errors are the same, only its times differ).
if (!exists("out")) out = 'bench/speed-vs-error.png'
if (!exists("jitdata")) jitdata = 'bench/data/luajit.dat'
if (!exists("pucdata")) pucdata = 'bench/data/lua5.4.dat'
have(f) = system('[ -f "' . f . '" ] && echo 1 || echo 0') + 0
hasjit = have(jitdata); haspuc = have(pucdata)
if (!hasjit && !haspuc) { print "bench/plot.gp: no data files"; exit status 1 }

set terminal pngcairo size 1650,560 font ",10"
set output out
set multiplot layout 1,3 title "polygon.lua (blue) against the tutorial's formulas (red): time per call against error (errors of 0 drawn at the floor)"
set logscale xy
set format y "1e%T"
set xlabel "time per call (ns)"
set grid
set key top left font ",9"
set offsets graph 0.15, graph 0.15, graph 0.2, graph 0.2

titles = "'Areas and centres, polygons at 1e9: max error (ulp, floor 0.01)' 'Near-degenerate input: wrong answers (%, floor 0.01)' 'Collision response: max relative error of (dx, dy) (floor 1e-17)'"
ylabels = "'max error (ulp)' 'wrong answers (%)' 'max relative error'"

# labels are spread vertically by the 4th column (the row's place in its panel), in decades
spreads = "1.0 0.35 1.2"
do for [p = 1:3] {
  s = word(spreads, p) + 0
  set title word(titles, p)
  set ylabel word(ylabels, p)
  m = 2 * (p - 1)
  b = m + 1
  if (hasjit && haspuc) {
    plot jitdata index m using 1:2 with points pt 7 ps 1.4 lc rgb "#1f5fbf" title "polygon.lua, LuaJIT", \
         jitdata index b using 1:2 with points pt 5 ps 1.4 lc rgb "#c0392b" title "baseline, LuaJIT", \
         pucdata index m using 1:2 with points pt 6 ps 1.4 lc rgb "#1f5fbf" title "polygon.lua, Lua 5.4", \
         pucdata index b using 1:2 with points pt 4 ps 1.4 lc rgb "#c0392b" title "baseline, Lua 5.4", \
         jitdata index m using 1:($2 * 10**(s * ($4 - 1.5))):3 with labels left offset 1,0.6 font ",8" tc rgb "#1f5fbf" notitle, \
         jitdata index b using 1:($2 * 10**(s * ($4 - 1.5))):3 with labels right offset -1,-0.6 font ",8" tc rgb "#c0392b" notitle
  } else {
    f = hasjit ? jitdata : pucdata
    plot f index m using 1:2 with points pt 7 ps 1.4 lc rgb "#1f5fbf" title "polygon.lua", \
         f index b using 1:2 with points pt 5 ps 1.4 lc rgb "#c0392b" title "baseline", \
         f index m using 1:($2 * 10**(s * ($4 - 1.5))):3 with labels left offset 1,0.6 font ",8" tc rgb "#1f5fbf" notitle, \
         f index b using 1:($2 * 10**(s * ($4 - 1.5))):3 with labels right offset -1,-0.6 font ",8" tc rgb "#c0392b" notitle
  }
}
unset multiplot
