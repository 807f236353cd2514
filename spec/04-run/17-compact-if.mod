MODULE compact_if
! @format 3
! @section 4.17
! @expect ok
! @description A compact IF runs its single statement only when the condition is true (section 4.17).
! @output yes
! @output count=1
! @exit 0
  VAR num count;
  PROC main()
    IF count = 0 TPWrite "yes";
    IF count = 1 TPWrite "no";
    IF count = 0 count := count + 1;
    IF count = 0 count := count + 10;
    TPWrite "count=" \Num:=count;
  ENDPROC
ENDMODULE
