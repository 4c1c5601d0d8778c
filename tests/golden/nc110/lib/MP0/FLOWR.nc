; FLOWR (cls-recursion): calls itself.
E30=E30+1
(CLS,FLOWR)
