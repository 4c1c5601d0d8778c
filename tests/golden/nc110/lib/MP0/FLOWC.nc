; FLOWC (cls-depth): calls FLOWD; from FLOWB that would be a third open call.
E31=E31+1
(CLS,FLOWD)
