MODULE conveyor
  VAR num speed;
ENDMODULE
