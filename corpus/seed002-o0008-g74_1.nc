(source: shared/seeds/002_51941964e440f920.txt)
(section: 3.23.7 轴向凹槽切削循环 G74.1 - 代码示例, example O0008)
(profile: gsk)
(rules: G74_1.EX.O0008)
(the seed assumes a 4 mm grooving tool and a least input increment of 0.0001 mm:)
(P30000 = 3 mm, Q50000 = 5 mm in least increments, parameter 182.7; no I word is given)
(transcription: comments joined from the seed's wrapped lines)
O0008;
G00 X70 Z10 M3 S500;	(快速定位,启动主轴,指定转速500)
G74.1 X66 Z0 P30000 Q50000 H-10 D-20 A45 B60;	(槽尺寸:槽深 10mm,底宽 20mm,啮合角 45°和 60°)
G74.1 R0.5;	(定位到加工起点,此时刀宽会影响实际凹槽起点, X 方向需要加上刀具宽度, Z轴每次进刀5mm, 退刀0.5mm)
M30;
