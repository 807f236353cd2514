spec --impl 'sh spec-impl-tasks-swap.sh {mode} {options} {tasks} {files}' spec-impl-tasks-cases
