; FLOWS (cls-recursion): calls FLOWT, which calls FLOWS again.
(CLS,FLOWT)
