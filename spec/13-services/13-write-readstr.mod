MODULE write_readstr
! @format 3
! @section 13
! @expect ok
! @description Write writes its text, then the value of \Num, \Bool, \Pos, \Orient or \Dnum as TPWrite does, then a line feed unless \NoNewLine; ReadStr reads one line back without its line feed, and EOF at the end of the file.
! @output Count: 42
! @output Ratio 0.25
! @output Flag TRUE
! @output Pos [1,2.5,-3]
! @output Orient [1,0,0,0]
! @output Dnum 4294967295
! @output no newline
! @output end: EOF
! @exit 0
  VAR iodev file;
  VAR string line;
  PROC main()
    Open "HOME:" \File:="write.txt", file \Write;
    Write file, "Count: " \Num:=42;
    Write file, "Ratio " \Num:=0.25;
    Write file, "Flag " \Bool:=TRUE;
    Write file, "Pos " \Pos:=[1, 2.5, -3];
    Write file, "Orient " \Orient:=[1, 0, 0, 0];
    Write file, "Dnum " \Dnum:=4294967295;
    Write file, "no " \NoNewLine;
    Write file, "newline";
    Close file;
    Open "HOME:/write.txt", file \Read;
    line := ReadStr(file);
    WHILE line <> EOF DO
      TPWrite line;
      line := ReadStr(file);
    ENDWHILE
    TPWrite "end: " + line;
    Close file;
    RemoveFile "HOME:/write.txt";
  ENDPROC
ENDMODULE
