MODULE assignment_persistent
! @format 3
! @section 4.5
! @section 2.23
! @expect ok
! @description An assignment may change a persistent (section 4.5); the new value is read back at once.
! @output pcounter=1
! @output pcounter=2
! @exit 0
  PERS num pcounter := 0;
  PROC main()
    pcounter := pcounter + 1;
    TPWrite "pcounter=" \Num:=pcounter;
    pcounter := pcounter + 1;
    TPWrite "pcounter=" \Num:=pcounter;
  ENDPROC
ENDMODULE
