Module reserved_words_mixed_case
! @section 2.3
! @section 2.4
! @expect ok
! @description Reserved words are recognised in any mix of letter case.
  Var num x;
  LoCaL Var bool b := False;
  Proc main()
    If x > 0 Or b Xor TRUE Then
      x := 0;
    EndIf
    Return;
  EndProc
  Func num f()
    Return 1;
  EndFunc
EndModule
