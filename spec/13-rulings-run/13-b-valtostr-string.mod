MODULE rulings_valtostr_string
! @format 3
! @section 13
! @section 2.7
! @expect ok
! @description R-13-b: ValToStr writes a string as RAPID writes a string literal (section 2.7): in double quotes, with "" for a quote, \\ for a backslash and \hh for a control character, also inside records and arrays.
! @output "abc"
! @output ""
! @output "a""b"
! @output "a\\b"
! @output "\07"
! @output ["ab",1]
! @output ["x","y""z"]
! @exit 0
  RECORD named
    string name;
    num value;
  ENDRECORD

  PROC main()
    VAR named r := ["ab", 1];
    VAR string a{2} := ["x", "y""z"];
    TPWrite ValToStr("abc");
    TPWrite ValToStr("");
    TPWrite ValToStr("a""b");
    TPWrite ValToStr("a\\b");
    TPWrite ValToStr("\07");
    TPWrite ValToStr(r);
    TPWrite ValToStr(a);
  ENDPROC
ENDMODULE
