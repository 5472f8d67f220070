; Highlighting for walls files: the same classes as the TextMate grammar and the
; language server's semantic tokens.
(wall_keyword) @keyword
(defaults_keyword) @keyword
(general_keyword) @keyword
(property_name) @property
(type_name) @type.builtin
(number) @number
(word) @error
(comment) @comment
