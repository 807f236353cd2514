MODULE statement_list_missing_terminato
! @section 4.3
! @section 4.2
! @expect syntax-error 9:5
! @description A simple statement ends with ';'.
  VAR num x;
  PROC main()
    x := 1
    x := 2;
  ENDPROC
ENDMODULE
