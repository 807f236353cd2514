MODULE present_use
! @format 3
! @section 11
! @section 5.2
! @expect ok
! @description Present returns FALSE only for an absent optional parameter, TRUE otherwise (chapter 11): for a present optional parameter and for a required one.
! @output required=TRUE optional=FALSE
! @output required=TRUE optional=TRUE
! @exit 0
  PROC p(num r \num o)
    TPWrite "required=" + ValToStr(Present(r)) + " optional=" + ValToStr(Present(o));
  ENDPROC
  PROC main()
    p 1;
    p 1 \o:=2;
  ENDPROC
ENDMODULE
