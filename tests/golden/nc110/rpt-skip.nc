; rpt-skip: RPT and ERP may not stand in a block with the block-skip field '/'
; (decision 20; a skipped RPT or ERP would unbalance the loop; NC3021).
/(RPT,2)
E30=1
(ERP)
(RPT,2)
E31=1
/(ERP)
