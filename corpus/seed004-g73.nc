(source: shared/seeds/004_e17a91cae76bcf9f.txt)
(section: 一.FANUC 0i - B. 程序, the G73 example with G70)
(profile: fanuc-0i-f)
(rules: G73.EX, G70.EX)
(transcription: the seed repeats 'G2Z-45R25' and 'N11G1Z-50' after its code block, a page)
( layout duplicate, kept once here; the two ';' of the seed are kept; the seed's program)
( has no program number and no M30/M02: it ends at T0100)
M03S1000
T0101
G0X70Z2
G73U5W0R4
G73P10Q11U0.2W0.1F0.1
N10G01X50Z0
G3X40Z-15R22
G2Z-45R25;
N11G1Z-50;
G70P10Q11
G0X100Z200
T0100
