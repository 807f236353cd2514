MODULE callbyvar_use
! @format 3
! @section 13
! @section 4.6
! @expect ok
! @description CallByVar Name, Number calls the procedure named Name followed by Number (installed-facts.md section 4: ("proc", 3) calls proc3).
! @output proc3
! @output proc1
! @exit 0
  PROC proc1()
    TPWrite "proc1";
  ENDPROC
  PROC proc3()
    TPWrite "proc3";
  ENDPROC
  PROC main()
    VAR num reg1 := 1;
    CallByVar "proc", 3;
    CallByVar "proc", reg1;
  ENDPROC
ENDMODULE
