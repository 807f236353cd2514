MODULE unknown_procedure_reached
! @format 3
! @section 4.6
! @section 13
! @options allow-unknown
! @expect ok
! @description With --allow-unknown a call of a procedure neither declared nor installed is a warning; reaching it is ERR_REFUNKPRC (ch. 12).
! @output before
! @exit 1
! @error ERR_REFUNKPRC 13:5
  PROC main()
    TPWrite "before";
    NoSuchProcedure 1, 2;
    TPWrite "after";
  ENDPROC
ENDMODULE
