%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%
MODULE header_block
! @section 9.2
! @expect ok
! @description A %%% header block before MODULE is accepted by default (dialect extension).
  VAR num x;
ENDMODULE
