MODULE default_initial_values
! @format 3
! @section 2.22
! @expect ok
! @description A variable without initial value, and each component or element of one, receives the initial value of its type (section 2.22): 0 for num and dnum, FALSE for bool, "" for string.
! @output num=0
! @output dnum zero=TRUE
! @output bool=FALSE
! @output string length=0
! @output pos=[0,0,0]
! @output array zero=TRUE
! @output record=0 FALSE 0
! @exit 0
  RECORD item
    num count;
    bool done;
    string name;
  ENDRECORD
  VAR num n;
  VAR dnum d;
  VAR bool b;
  VAR string s;
  VAR pos p;
  VAR num a{2, 2};
  VAR item it;
  PROC main()
    TPWrite "num=" \Num:=n;
    TPWrite "dnum zero=" \Bool:=d = 0;
    TPWrite "bool=" \Bool:=b;
    TPWrite "string length=" \Num:=StrLen(s);
    IF p = [0, 0, 0] TPWrite "pos=[0,0,0]";
    TPWrite "array zero=" \Bool:=a = [[0, 0], [0, 0]];
    TPWrite "record=" + NumToStr(it.count, 0) + " " + ValToStr(it.done) + " " + NumToStr(StrLen(it.name), 0);
  ENDPROC
ENDMODULE
