; FLOWT (cls-recursion): calls FLOWS, which called it.
(CLS,FLOWS)
