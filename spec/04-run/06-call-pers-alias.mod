MODULE call_pers_alias
! @format 3
! @section 5.2
! @expect ok
! @description A pers parameter is an alias of its persistent argument (section 5.2): the update is visible through the persistent at once.
! @output during=7
! @output after=7
! @exit 0
  PERS num level := 1;
  PROC change(PERS num a)
    a := 7;
    TPWrite "during=" \Num:=level;
  ENDPROC
  PROC main()
    change level;
    TPWrite "after=" \Num:=level;
  ENDPROC
ENDMODULE
