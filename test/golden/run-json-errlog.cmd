run --json ../../spec/06-backward/7-5-errlog-skipwarn.mod
