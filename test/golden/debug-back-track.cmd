debug --robot ../../spec/motion/robot/track.robot --script debug-back-track.dbg ../../spec/motion/52-backward-track.mod
