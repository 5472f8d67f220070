; A block folds: a wall or a defaults block with its statements.
(wall_block) @fold
(defaults_block) @fold
