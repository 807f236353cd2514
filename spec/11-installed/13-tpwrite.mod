MODULE tpwrite_text_and_num
! @format 3
! @section 13
! @expect ok
! @description TPWrite writes one line: its text, followed by the optional value as text (installed-facts.md section 1); a num holding an integer is written without decimals.
! @output Hello
! @output n=5
! @output n=-12
! @output
! @exit 0
  PROC main()
    TPWrite "Hello";
    TPWrite "n=" \Num:=5;
    TPWrite "n=" \Num:=-12;
    TPWrite "";
  ENDPROC
ENDMODULE
