MODULE readstr_switches
! @format 3
! @section 13
! @expect ok
! @description ReadStr \Delim ends a field at any of its characters (which is consumed), \DiscardHeaders skips delimiters before the field, \RemoveCR drops the carriage return of a CR LF line, a field is at most 80 characters, and \Line reads that line of the file.
! @output a
! @output b
! @output []
! @output c
! @output head
! @output [x]
! @output 01234567890123456789012345678901234567890123456789012345678901234567890123456789
! @output length 5
! @output EOF
! @output line 3: x
! @exit 0
  VAR iodev file;
  VAR string s;
  PROC main()
    Open "TEMP:/fields.txt", file \Write;
    Write file, "a;b;;c";
    Write file, ";;;head" + "\0D";
    Write file, "x";
    Write file, "0123456789012345678901234567890123456789" \NoNewLine;
    Write file, "0123456789012345678901234567890123456789abcde";
    Close file;
    Open "TEMP:/fields.txt", file \Read;
    TPWrite ReadStr(file \Delim:=";");
    TPWrite ReadStr(file \Delim:=";");
    TPWrite "[" + ReadStr(file \Delim:=";") + "]";
    TPWrite ReadStr(file \Delim:=";\0A");
    TPWrite ReadStr(file \Delim:=";" \RemoveCR \DiscardHeaders);
    s := ReadStr(file \RemoveCR);
    TPWrite "[" + s + "]";
    TPWrite ReadStr(file);
    s := ReadStr(file);
    TPWrite "length " \Num:=StrLen(s);
    TPWrite ReadStr(file);
    TPWrite "line 3: " + ReadStr(file \Line:=3);
    Close file;
  ENDPROC
ENDMODULE
