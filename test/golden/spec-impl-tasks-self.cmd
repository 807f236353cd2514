spec --impl 'sh spec-impl-self.sh {mode} {options} {tasks} {files}' -v spec-impl-tasks-cases
