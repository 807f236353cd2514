MODULE utf8_in_comment
! @section 2.1
! @section 2.10
! @expect ok
! @description Any UTF-8 symbol, emoji included, may appear in a comment.
  VAR num x;
  PROC main()
    ! UTF-8 in a comment: 注释 éè 😀 Δ
    x := 1; ! ✓ after a statement
  ENDPROC
ENDMODULE
