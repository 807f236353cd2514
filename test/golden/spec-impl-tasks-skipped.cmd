spec --impl 'sh spec-impl-self.sh {mode} {options} {files}' -v spec-impl-tasks-cases
