MODULE rulings_string_positions
! @format 3
! @section 13
! @section 2.13
! @expect ok
! @description R-13-c: positions count bytes from 1 (the UTF-8 letter é takes two); StrFind and StrMatch may start at 1..StrLen+1 and return StrLen+1 when nothing is found; StrMatch of the empty pattern returns ChPos; StrPart(s, StrLen+1, 0) is the empty string.
! @output StrFind xyz=9
! @output StrFind from 9=9
! @output StrFind from 8=8
! @output StrFind \NotInSet=9
! @output StrFind in empty=1
! @output StrMatch box=9
! @output StrMatch bo from 4=9
! @output StrMatch empty from 2=2
! @output StrMatch empty from 9=9
! @output StrPart(s,9,0)=[]
! @output StrPart(s,8,1)=[s]
! @output StrLen=4
! @output StrFind b=4
! @output StrPart=[é]
! @output StrMemb 4=TRUE
! @exit 0
  PROC main()
    VAR string s := "Robotics";
    VAR string u := "aéb";
    TPWrite "StrFind xyz=" \Num:=StrFind(s, 1, "xyz");
    TPWrite "StrFind from 9=" \Num:=StrFind(s, 9, "s");
    TPWrite "StrFind from 8=" \Num:=StrFind(s, 8, "s");
    TPWrite "StrFind \\NotInSet=" \Num:=StrFind(s, 1, "Rbciost" \NotInSet);
    TPWrite "StrFind in empty=" \Num:=StrFind("", 1, "a");
    TPWrite "StrMatch box=" \Num:=StrMatch(s, 1, "box");
    TPWrite "StrMatch bo from 4=" \Num:=StrMatch(s, 4, "bo");
    TPWrite "StrMatch empty from 2=" \Num:=StrMatch(s, 2, "");
    TPWrite "StrMatch empty from 9=" \Num:=StrMatch(s, 9, "");
    TPWrite "StrPart(s,9,0)=[" + StrPart(s, 9, 0) + "]";
    TPWrite "StrPart(s,8,1)=[" + StrPart(s, 8, 1) + "]";
    TPWrite "StrLen=" \Num:=StrLen(u);
    TPWrite "StrFind b=" \Num:=StrFind(u, 1, "b");
    TPWrite "StrPart=[" + StrPart(u, 2, 2) + "]";
    TPWrite "StrMemb 4=" \Bool:=StrMemb(u, 4, "b");
  ENDPROC
ENDMODULE
