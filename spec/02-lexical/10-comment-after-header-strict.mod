%%%
  VERSION:1
%%%
! exported by the controller
MODULE comment_after_header_strict
! @section 9.2
! @section 2.10
! @expect syntax-error 1:1
! @options strict
! @description In strict mode the header block is refused first, at 1:1, before the comment that follows it.
  VAR num x;
ENDMODULE
