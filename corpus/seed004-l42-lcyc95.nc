; (source: shared/seeds/004_e17a91cae76bcf9f.txt)
; (section: 二.SINUMERIK 802S/c - B. 程序, LCYC95 main program and contour L42)
; (profile: sinumerik-802s)
; (rules: SEED004.EX.L42, SEED004.THREAD)
; (layout: SINUMERIK comments start with ';'; the main program comes first, then after its M02 the)
; ( contour subprogram as the seed prints it: a line L42.spf of its own, then its blocks; 'L42. spf' [OCR space] written 'L42.spf')
; (chamfers are 45 x 1.5)
; (transcription: the seed writes decimals with a space after the point - 'X20. 8Z-25. 8',)
; ( 'X31. 6Z-39. 5', 'Z-46. 5', 'Z-58. 5', 'Z-66. 5' - joined here: X20.8 Z-25.8 etc.)
T1D1
M03S800
G0X50Z2
_CNAME="L42"
R105=1 R106=0.3 R108=2 R109=7
R110=1.5 R111=0.4 R112=0.25
LCYC95
R105=5 R106=0
LCYC95
G0X200Z200
T1D0
T3D1
G0X40Z-43
R100=38 R101=-45 R102=38 R103=-60
R104=1.5 R105=1 R106=0.2 R109=2
R110=3 R111=0.975 R112=0 R113=4
R114=1
LCYC97
G0X100
Z100
T3D0
M05
M02
L42.spf
G1X0Z0
G3X20.8Z-25.8K-15I0
G2X31.6Z-39.5CR=8
G1Z-45
X35
X38Z-46.5
Z-58.5
X35Z-60
Z-65
X39
X42Z-66.5
Z-75
M02
