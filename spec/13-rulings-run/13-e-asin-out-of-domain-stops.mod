MODULE rulings_asin_domain
! @format 3
! @section 13
! @section 7.1
! @expect ok
! @description R-13-e: an argument outside the function's domain is ERR_ARGVALERR: ASin(2) stops the task at the statement that calls it.
! @output ASin(1)=90
! @exit 1
! @error ERR_ARGVALERR 15:5
  PROC main()
    VAR num v := 1;
    VAR num a;
    TPWrite "ASin(1)=" \Num:=ASin(v);
    v := 2;
    a := ASin(v);
    TPWrite "not reached";
  ENDPROC
ENDMODULE
