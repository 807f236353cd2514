MODULE function_parameters
! @format 3
! @section 5.5
! @section 5.2
! @expect ok
! @description Function parameters follow section 5.2 as procedure parameters do: an in parameter is a copy, a var parameter an alias whose update the caller sees after the call.
! @output result=11
! @output copy=1
! @output shared=5
! @exit 0
  FUNC num f(num a, VAR num b)
    a := 10;
    b := 5;
    RETURN a + 1;
  ENDFUNC
  PROC main()
    VAR num copy := 1;
    VAR num shared := 1;
    TPWrite "result=" \Num:=f(copy, shared);
    TPWrite "copy=" \Num:=copy;
    TPWrite "shared=" \Num:=shared;
  ENDPROC
ENDMODULE
