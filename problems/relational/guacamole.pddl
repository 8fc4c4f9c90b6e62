; foon2pddl, encoding relational, level 3: 22 of 101 units after relevance pruning
; goal: guacamole (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 18 (avocado 1, bowl 1, cilantro 1, cutting board 5, fork 1, guacamole 1, juicer 1, knife 1, lime 1, lime juice 1, onion 1, salt 1, spoon 1, tomato 1)
; objects: 5 x cutting board (empty): FOON's plan, unfolded, takes one out of that state each time it fires pick-and-place at 06-tomato_soup.foon:3, pick-and-place at 06-tomato_soup.foon:42, pick-and-place at 07-guacamole.foon:3, pick-and-place at 07-guacamole.foon:52, ... (1 more), and no unit puts one back
(define (problem make_guacamole)
  (:domain foon-relational-71e09b19)
  (:objects
    avocado_1 - avocado
    bowl_1 - bowl
    cilantro_1 - cilantro
    cutting_board_1 - cutting_board
    cutting_board_2 - cutting_board
    cutting_board_3 - cutting_board
    cutting_board_4 - cutting_board
    cutting_board_5 - cutting_board
    guacamole_1 - guacamole
    juicer_1 - juicer
    lime_1 - lime
    lime_juice_1 - lime_juice
    onion_1 - onion
    salt_1 - salt
    tomato_1 - tomato
  )
  (:init
    (is avocado_1 avocado_whole)
    (is bowl_1 bowl_empty)
    (is cilantro_1 cilantro_fresh)
    (is cutting_board_1 cutting_board_empty)
    (is cutting_board_2 cutting_board_empty)
    (is cutting_board_3 cutting_board_empty)
    (is cutting_board_4 cutting_board_empty)
    (is cutting_board_5 cutting_board_empty)
    (is guacamole_1 not-yet-made)
    (is juicer_1 juicer_empty)
    (is lime_1 lime_whole)
    (is lime_juice_1 not-yet-made)
    (is onion_1 onion_whole)
    (is salt_1 salt_granulated)
    (is tomato_1 tomato_whole)
    (occupied fork_plain)
    (occupied knife_plain)
    (occupied spoon_plain)
  )
  (:goal (and
    (goal-reached)
  ))
)
