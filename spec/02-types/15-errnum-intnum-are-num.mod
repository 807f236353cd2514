MODULE errnum_intnum_are_num
! @format 2
! @section 2.15
! @expect ok
! @description errnum and intnum are aliases of num: they mix freely with num.
  VAR errnum e;
  VAR intnum i;
  VAR num n;
  PROC main()
    n := e + i;
    e := n;
    i := e * 2;
  ENDPROC
ENDMODULE
