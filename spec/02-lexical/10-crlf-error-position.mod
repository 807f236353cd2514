MODULE crlf_error_position
! @section 2.10
! @section 2.2
! @expect syntax-error 10:12
! @description Line numbers in a file with CR LF line breaks: each CR LF pair ends one line.
  VAR num x;
  PROC main()
    ! lines end with CR LF; CR LF counts as one line break
    x := 1;
    x := 2 3;
  ENDPROC
ENDMODULE
