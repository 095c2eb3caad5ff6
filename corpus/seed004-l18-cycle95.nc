; (source: shared/seeds/004_e17a91cae76bcf9f.txt)
; (section: 三.SINUMERIK 802D - B. 加工程序, CYCLE95 main program and contour L18)
; (profile: sinumerik-802d)
; (rules: SEED004.EX.L18, SEED004.THREAD)
; (layout: SINUMERIK comments start with ';'; the main program comes first, then after its M02 the)
; ( contour subprogram as the seed prints it: a line L18.spf of its own, then its blocks; 'L18.spf' kept)
; (chamfers are 45 x 1.5)
; (transcription: none needed; CYCLE95/CYCLE97 argument lists kept as written, comma and space)
T1D1
M03S800
G0X0Z2
CYCLE95("L18", 1.5, 0.3, 0.3, 0.2, 0.2, 0.2, 0.2, 9, 0, 0, 1)
G0X100Z100
T1D0
T2D1
G0X32Z-30.5
G1X27
G0X100
Z100
T2D0
T3D1
G0X28Z-14
CYCLE97(1.5, 3, -16, -27.5, 30, 30, 2, 2, 1.35, 0.1, 0, 0, 3, 2, 3, 1)
G0X100
Z100
T3D0
M05
M02
L18.spf
G1X0Z0F0.2
G03X20Z-10CR=10
G1Z-16
X27
X30Z-17.5
Z-30.5
X40
Z-35.5
G02Z-50CR=20
G1X50Z-58
Z-70
RET
