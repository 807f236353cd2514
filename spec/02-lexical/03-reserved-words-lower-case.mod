module reserved_words_lower_case (sysmodule, nostepin)
! @section 2.3
! @section 2.4
! @expect ok
! @description Reserved words are recognised in lower case: identifiers that differ only in case are the same, reserved words included.
  var num x;
  const num c := 1;
  proc main()
    if x > 0 and true then
      x := x div 2;
    elseif not x = 0 then
      x := x mod 2;
    else
      while x < 10 do
        x := x + 1;
      endwhile
    endif
    for i from 1 to 3 step 1 do
      x := i;
    endfor
    test x
    case 1:
      x := 0;
    default:
      x := 1;
    endtest
  endproc
endmodule
