MODULE latin1_file_comment_and_string
! @section 2.1
! @section 2.10
! @expect ok
! @description A file in ISO 8859-1 (byte 0xE9 in a comment and a string, not valid UTF-8) is accepted.
  VAR string s;
  PROC main()
    ! café crème brûlée
    s := "café";
  ENDPROC
ENDMODULE
