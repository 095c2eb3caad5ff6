(source: shared/seeds/000_036281bf73fad5d1.txt)
(section: 4.2.1 外徑粗削迴圈 [G71] - 類型 I, 例 and 程式例, in their spirit)
(profile: fanuc-0i-f)
(rules: G71.FMT.ZX, G71.TYPE.SELECT, G71.HEAD.G0G1, G71.T1.MONO, G71.FST, G70.EX)
(not a seed program: seed 000 shows only skeletons - 'G71 U10.0 R5.0; G71 P100 Q200...;)
( N100 X[U]_;' and 'G71U1.0R0.5; G71P10Q20; N10G00X0; ... N20X50.;' - so this short)
( outer-diameter type I program follows them: ZX plane, block N100 moves X only,)
( shape monotonic in X and Z, every point at or below the start height X52 with U+.)
(the F0.1 inside N100...N200 is ignored by G71 and used by G70, G71.FST)
G00 X52.0 Z2.0;
G71 U2.0 R0.5;
G71 P100 Q200 U0.4 W0.1 F0.25;
N100 G00 X16.0;
G01 Z0 F0.1;
X20.0 Z-2.0;
Z-20.0;
G02 X30.0 Z-25.0 R5.0;
G01 X40.0 Z-40.0;
Z-50.0;
N200 X50.0;
G70 P100 Q200;
M30;
