; An origin that does not declare an axis (NC-110 §2.13.1.1, §2.13.1.2, §2.13.1.7: the
; origins file holds records with their axes); decision 30.
; Profile frame-origins: origin 2 declares X Y, origin 3 X Y B.
; Checks (ncc check: the dry run reports each error and goes on): (UAO,2,Z), (UOT,3,Z1)
; and (RQO,2,B1) name an axis the origin does not declare: NC4056 at the axis operand,
; naming the axes the origin declares.
(UAO,2,Z)
(UOT,3,Z1)
(RQO,2,B1)
