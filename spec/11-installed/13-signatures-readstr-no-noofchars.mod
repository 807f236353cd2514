MODULE sig_readstr_no
! @format 2
! @section 3.11
! @section 13
! @expect semantic-error 11:25
! @description ReadStr has no \NoOfChars (ABB: ReadStr (IODevice [\Delim] [\RemoveCR] [\DiscardHeaders] [\Time] [\Line]); the number of characters belongs to ReadStrBin): the argument is refused at its backslash.
  VAR iodev log;
  VAR string line;
  PROC main()
    line := ReadStr(log \RemoveCR);
    line := ReadStr(log \NoOfChars:=10);
  ENDPROC
ENDMODULE
