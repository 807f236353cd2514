MODULE late_binding_types
! @format 3
! @section 4.6
! @section 3.11
! @section 5.2
! @expect ok
! @description Section 4.6: the rules for the arguments of a late-bound call are those of a function call, and section 3.11 asks for equal types: an argument of another type than its parameter raises ERR_CALLPROC when the call runs (chapter 12), and the procedure is not entered. Records are equal only as the same type, whatever their components.
! @output text=hello
! @output num to string: 
! @output callproc
! @output string to num: 
! @output callproc
! @output pos to own record: 
! @output callproc
! @output num array to num: 
! @output callproc
! @output bool=TRUE
! @output pos=[1,2,3]
! @exit 0
  RECORD point
    num x;
    num y;
    num z;
  ENDRECORD
  VAR string text := "hello";
  VAR pos p := [1, 2, 3];
  VAR num list{2} := [1, 2];
  VAR bool flag := TRUE;
  PROC show_text(string s)
    TPWrite "text=" + s;
  ENDPROC
  PROC show_num(num n)
    TPWrite "num=" \Num:=n;
  ENDPROC
  PROC show_point(point q)
    TPWrite "point";
  ENDPROC
  PROC show_bool(bool b)
    TPWrite "bool=" \Bool:=b;
  ENDPROC
  PROC show_pos(pos q)
    TPWrite "pos=" \Pos:=q;
  ENDPROC
  PROC main()
    % "show_text" % text;
    TPWrite "num to string: ";
    % "show_text" % 5;
    TPWrite "string to num: ";
    % "show_num" % text;
    TPWrite "pos to own record: ";
    % "show_point" % p;
    TPWrite "num array to num: ";
    % "show_num" % list;
    % "show_bool" % flag;
    % "show_pos" % p;
  ERROR
    IF ERRNO = ERR_CALLPROC THEN
      TPWrite "callproc";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
