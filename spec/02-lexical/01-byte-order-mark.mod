MODULE byte_order_mark
! @section 2.1
! @expect ok
! @description A UTF-8 byte-order mark before MODULE is accepted by default (dialect extension).
  VAR num x;
  PROC main()
    x := 1;
  ENDPROC
ENDMODULE
