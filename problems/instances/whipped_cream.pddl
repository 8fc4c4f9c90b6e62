; foon2pddl, encoding instances, level 3: 25 of 101 units after relevance pruning
; goal: whipped cream (3 candidate nodes)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 21 (avocado 1, baking powder 1, banana 1, bowl 1, cutting board 1, electric mixer 1, flour 1, fork 1, heavy cream 1, honey 1, juicer 1, knife 1, lime 1, mixing bowl 1, salt 1, spatula 1, spoon 1, strawberry 1, sugar 1, whipped cream 1, whisk 1)
(define (problem make_whipped_cream)
  (:domain foon-instances)
  (:objects
    avocado_1 - avocado
    baking_powder_1 - baking_powder
    banana_1 - banana
    bowl_1 - bowl
    cutting_board_1 - cutting_board
    electric_mixer_1 - electric_mixer
    flour_1 - flour
    fork_1 - fork
    heavy_cream_1 - heavy_cream
    honey_1 - honey
    juicer_1 - juicer
    knife_1 - knife
    lime_1 - lime
    mixing_bowl_1 - mixing_bowl
    salt_1 - salt
    spatula_1 - spatula
    spoon_1 - spoon
    strawberry_1 - strawberry
    sugar_1 - sugar
    whipped_cream_1 - whipped_cream
    whisk_1 - whisk
  )
  (:init
    (is avocado_1 avocado_whole)
    (is baking_powder_1 baking_powder_powder)
    (is banana_1 banana_whole)
    (is bowl_1 bowl_empty)
    (is cutting_board_1 cutting_board_empty)
    (is electric_mixer_1 electric_mixer_off)
    (is flour_1 flour_powder)
    (is fork_1 fork_plain)
    (is heavy_cream_1 heavy_cream_in_carton)
    (is honey_1 honey_in_jar)
    (is juicer_1 juicer_empty)
    (is knife_1 knife_plain)
    (is lime_1 lime_whole)
    (is mixing_bowl_1 mixing_bowl_empty)
    (is salt_1 salt_granulated)
    (is spatula_1 spatula_plain)
    (is spoon_1 spoon_plain)
    (is strawberry_1 strawberry_whole)
    (is sugar_1 sugar_granulated)
    (is whipped_cream_1 not-yet-made)
    (is whisk_1 whisk_plain)
    (occupied fork_plain)
    (occupied juicer_empty)
    (occupied knife_plain)
    (occupied spatula_plain)
    (occupied spoon_plain)
    (occupied whisk_plain)
  )
  (:goal (and
    (goal-reached)
  ))
)
