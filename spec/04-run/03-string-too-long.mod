MODULE string_too_long
! @format 3
! @section 2.13
! @section 3.12
! @section 12
! @expect ok
! @description A string holds at most 80 bytes (section 2.13): concatenating 40 and 41 bytes raises ERR_STRTOOLNG (chapter 12) at the assignment.
! @exit 1
! @error ERR_STRTOOLNG 14:5
  PROC main()
    VAR string s40 := "0123456789012345678901234567890123456789";
    VAR string s41 := "01234567890123456789012345678901234567890";
    VAR string s;
    s := s40 + s41;
    TPWrite "after";
  ENDPROC
ENDMODULE
