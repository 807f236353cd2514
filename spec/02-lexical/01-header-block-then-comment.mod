%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%
! exported by the controller
MODULE header_block_then_comment
! @section 9.2
! @section 2.10
! @expect ok
! @description A comment line between the %%% header block and MODULE is accepted by default (dialect extension).
  VAR num x;
ENDMODULE
