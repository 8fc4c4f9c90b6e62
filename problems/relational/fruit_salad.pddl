; foon2pddl, encoding relational, level 3: 13 of 101 units after relevance pruning
; goal: fruit salad (2 candidate nodes)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 13 (banana 1, bowl 1, cutting board 3, fruit salad 1, honey 1, juicer 1, knife 1, lime 1, lime juice 1, spoon 1, strawberry 1)
(define (problem make_fruit_salad)
  (:domain foon-relational)
  (:objects
    banana_1 - banana
    bowl_1 - bowl
    cutting_board_1 - cutting_board
    cutting_board_2 - cutting_board
    cutting_board_3 - cutting_board
    fruit_salad_1 - fruit_salad
    honey_1 - honey
    juicer_1 - juicer
    knife_1 - knife
    lime_1 - lime
    lime_juice_1 - lime_juice
    spoon_1 - spoon
    strawberry_1 - strawberry
    jar_1 - jar
  )
  (:init
    (in jar_1 honey_1)
    (is banana_1 banana_whole)
    (is bowl_1 bowl_empty)
    (is cutting_board_1 cutting_board_empty)
    (is cutting_board_2 cutting_board_empty)
    (is cutting_board_3 cutting_board_empty)
    (is fruit_salad_1 not-yet-made)
    (is honey_1 honey_in_jar)
    (is jar_1 jar_contains_honey)
    (is juicer_1 juicer_empty)
    (is knife_1 knife_plain)
    (is lime_1 lime_whole)
    (is lime_juice_1 not-yet-made)
    (is spoon_1 spoon_plain)
    (is strawberry_1 strawberry_whole)
    (occupied knife_plain)
    (occupied spoon_plain)
  )
  (:goal (and
    (goal-reached)
  ))
)
