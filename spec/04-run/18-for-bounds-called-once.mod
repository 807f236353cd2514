MODULE for_bounds_called_once
! @format 3
! @section 4.18
! @section 3.1
! @expect ok
! @description The FROM, TO and STEP expressions are each evaluated exactly once (section 4.18), in the order they are written (reading).
! @output from
! @output to
! @output step
! @output 2
! @output 4
! @output 6
! @exit 0
  FUNC num bound(string name, num v)
    TPWrite name;
    RETURN v;
  ENDFUNC
  PROC main()
    FOR i FROM bound("from", 2) TO bound("to", 6) STEP bound("step", 2) DO
      TPWrite "" \Num:=i;
    ENDFOR
  ENDPROC
ENDMODULE
