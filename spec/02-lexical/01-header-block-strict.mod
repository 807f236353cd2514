%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%
MODULE header_block_strict
! @section 9.2
! @expect syntax-error 1:1
! @options strict
! @description In strict mode nothing may precede MODULE: a %%% header block is refused.
  VAR num x;
ENDMODULE
