; foon2pddl, encoding relational, level 3: 17 of 101 units after relevance pruning
; goal: fruit salad (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 20 (banana 1, bowl 1, cutting board 3, fruit salad 1, heavy cream 2, honey 2, juicer 1, knife 1, lime 1, lime juice 1, mixing bowl 1, spoon 1, strawberry 1, sugar 1, whipped cream 1, whisk 1)
; objects: 3 x cutting board (empty): FOON's plan, unfolded, takes one out of that state each time it fires pick-and-place at 07-guacamole.foon:52, pick-and-place at 09-fruit_salad.foon:3, pick-and-place at 09-fruit_salad.foon:34, and no unit puts one back
; label mismatch: 09-fruit_salad.foon:199: bowl lists whipped cream, which the unit puts on [fruit salad]
(define (problem make_fruit_salad)
  (:domain foon-relational-da776df9)
  (:objects
    banana_1 - banana
    bowl_1 - bowl
    cutting_board_1 - cutting_board
    cutting_board_2 - cutting_board
    cutting_board_3 - cutting_board
    fruit_salad_1 - fruit_salad
    heavy_cream_2 - heavy_cream
    honey_2 - honey
    juicer_1 - juicer
    lime_1 - lime
    lime_juice_1 - lime_juice
    mixing_bowl_1 - mixing_bowl
    strawberry_1 - strawberry
    sugar_1 - sugar
    whipped_cream_1 - whipped_cream
  )
  (:init
    (is banana_1 banana_whole)
    (is bowl_1 bowl_empty)
    (is cutting_board_1 cutting_board_empty)
    (is cutting_board_2 cutting_board_empty)
    (is cutting_board_3 cutting_board_empty)
    (is fruit_salad_1 not-yet-made)
    (is heavy_cream_2 not-yet-made)
    (is honey_2 not-yet-made)
    (is juicer_1 juicer_empty)
    (is lime_1 lime_whole)
    (is lime_juice_1 not-yet-made)
    (is mixing_bowl_1 mixing_bowl_empty)
    (is strawberry_1 strawberry_whole)
    (is sugar_1 sugar_granulated)
    (is whipped_cream_1 not-yet-made)
    (occupied carton_contains_heavy_cream)
    (occupied heavy_cream_in_carton)
    (occupied honey_in_jar)
    (occupied jar_contains_honey)
    (occupied knife_plain)
    (occupied spoon_plain)
    (occupied whisk_plain)
  )
  (:goal (and
    (goal-reached)
  ))
)
