(source: shared/seeds/003_22785bbc34f78b07.txt)
(section: 1、G71 内[外]径粗车复合循环 - 例 1, 图 1-44 阶梯轴, rewritten)
(profile: fanuc-0i-f)
(rules: G71.FMT.ZX, G71.TYPE.SELECT, HNC.G71.EX1)
(seed 003 example 1's cycle and contour N11...N20 in the FANUC 0i-F two-block form:)
( HNC 'G71U1.5R1P11Q20X0.6Z0.1F100' becomes 'G71 U1.5 R1;' + 'G71 P11 Q20 U0.6 W0.1 F100;')
(cycle start X54 Z3 as the seed's N5, not the A[52,3] of its text; the finishing pass is G70)
(not a seed program: tool changes, spindle and the parting-off of the original are left out;)
( F100 was mm/min there [G94], the toolpath does not depend on it)
G00 X54 Z3;
G71 U1.5 R1;
G71 P11 Q20 U0.6 W0.1 F100;
N11 G00 X0;
N12 G01 X10 Z-2;
N13 Z-20;
N14 G02 U10 W-5 R5;
N15 G01 W-10;
N16 G03 U14 W-7 R7;
N17 G01 Z-52;
N18 U10 W-10;
N19 W-25;
N20 X52;
G70 P11 Q20;
M30;
