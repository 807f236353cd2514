spec --impl 'sh spec-impl-tasks-store.sh {mode} {options} {tasks} {files}' spec-impl-tasks-cases
