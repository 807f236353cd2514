MODULE placeholder_not_reached
! @format 3
! @section 1.2
! @section 2.9
! @expect ok
! @description Only an executed placeholder is an error (section 1.2): a <SMT> in a branch that is not taken does nothing.
! @output done
! @exit 0
  VAR bool never := FALSE;
  PROC main()
    IF never THEN
      <SMT>
    ENDIF
    TPWrite "done";
  ENDPROC
ENDMODULE
