; ASC of a zone not defined (NC-110 §2.13.5.5); decision 35.
; Checks (ncc check): (ASC,2) before any (DSA,2,...) is NC4061 at the zone number;
; (ASC,E1) with E1 = 3 likewise at E1; after (DSA,3,...) (ASC,E1) is allowed; (DSC,1)
; of an undefined zone is allowed (it switches nothing on).
(ASC,2)
E1=3
(ASC,E1)
(DSA,3,X0 X1,Y0 Y1)
(ASC,E1)
(DSC,1)
