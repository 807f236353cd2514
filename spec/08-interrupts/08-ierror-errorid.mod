MODULE ierror_errorid
! @format 3
! @section 8
! @expect ok
! @statement-time 0
! @description IError with \ErrorId orders an interrupt for the entries of that number only: ErrWrite writes number 1 (no switch, TYPE_ERR), 2 (\W, TYPE_WARN) and 3 (\I, TYPE_STATE) in domain USER_DEF_ERR (doc/rulings.md R-8-l), so \ErrorId:=3 sees the \I entry alone. ReadErrData gives its number and type, \Title its header and \Str1..\Str5 the header, the reason and RL2..RL4 (R-8-y).
! @output id 3 state TRUE
! @output title [H]
! @output [H|R|two|three|four]
  VAR intnum info;
  VAR trapdata td;
  VAR errdomain dom;
  VAR num id;
  VAR errtype typ;
  VAR string t;
  VAR string s1;
  VAR string s2;
  VAR string s3;
  VAR string s4;
  VAR string s5;
  TRAP on_entry
    GetTrapData td;
    ReadErrData td, dom, id, typ \Title:=t \Str1:=s1 \Str2:=s2 \Str3:=s3 \Str4:=s4 \Str5:=s5;
    TPWrite "id " + NumToStr(id, 0) + " state " \Bool:=(typ = TYPE_STATE);
    TPWrite "title [" + t + "]";
    TPWrite "[" + s1 + "|" + s2 + "|" + s3 + "|" + s4 + "|" + s5 + "]";
  ENDTRAP
  PROC main()
    CONNECT info WITH on_entry;
    IError USER_DEF_ERR \ErrorId:=3, TYPE_ALL, info;
    ErrWrite "E", "error";
    ErrWrite \W, "W", "warning";
    ErrWrite \I, "H", "R" \RL2:="two" \RL3:="three" \RL4:="four";
    WaitTime 0.1;
  ENDPROC
ENDMODULE
