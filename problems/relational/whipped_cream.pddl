; foon2pddl, encoding relational, level 3: 4 of 101 units after relevance pruning
; goal: whipped cream (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 8 (bowl 1, heavy cream 2, mixing bowl 1, spatula 1, sugar 1, whipped cream 1, whisk 1)
(define (problem make_whipped_cream)
  (:domain foon-relational-733e9be4)
  (:objects
    bowl_1 - bowl
    heavy_cream_2 - heavy_cream
    mixing_bowl_1 - mixing_bowl
    sugar_1 - sugar
    whipped_cream_1 - whipped_cream
  )
  (:init
    (is bowl_1 bowl_empty)
    (is heavy_cream_2 not-yet-made)
    (is mixing_bowl_1 mixing_bowl_empty)
    (is sugar_1 sugar_granulated)
    (is whipped_cream_1 not-yet-made)
    (occupied carton_contains_heavy_cream)
    (occupied heavy_cream_in_carton)
    (occupied spatula_plain)
    (occupied whisk_plain)
  )
  (:goal (and
    (goal-reached)
  ))
)
