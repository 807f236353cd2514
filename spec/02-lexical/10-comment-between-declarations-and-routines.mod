MODULE comment_between_declarations_and
! @section 2.10
! @expect ok
! @description Comments between the last data declaration and the first routine (or statement) belong to the following list.
  VAR num x;
  ! belongs to the routine declaration list
  ! so does this one
  PROC main()
    VAR num y;
    ! belongs to the statement list
    ! so does this one
    y := x;
  ENDPROC
ENDMODULE
