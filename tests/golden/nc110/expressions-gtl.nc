; expressions-gtl: FEL, FEP and FEC read GTL elements (§2.12 seed L7693-7708: FEL(A,B)
; line l<A>, FEP point p<A>, FEC circle c<A>); here no block defines them: each is
; undefined at run time (decision 71, NC4050). The manual's examples L7733 and L10495.
; With USB = 0 the '/' block is not run (§2.4.4), so the error is at FEC, line 10.
USB=0
/E35=FEP(37,1)
(DIS,"FEP SKIPPED")
N171 E30=1
; error here
N172 E31=FEC(1,3)*2-400
