; foon2pddl, encoding instances, level 3: 4 of 101 units after relevance pruning
; goal: whipped cream (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 7 (bowl 1, heavy cream 1, mixing bowl 1, spatula 1, sugar 1, whipped cream 1, whisk 1)
; lanes: each instance changes state only as in the unfolded plan
(define (problem make_whipped_cream)
  (:domain foon-instances-fb378d59)
  (:objects
    bowl_1 - bowl
    heavy_cream_1 - heavy_cream
    mixing_bowl_1 - mixing_bowl
    spatula_1 - spatula
    sugar_1 - sugar
    whipped_cream_1 - whipped_cream
    whisk_1 - whisk
  )
  (:init
    (is bowl_1 bowl_empty)
    (is heavy_cream_1 heavy_cream_in_carton)
    (is mixing_bowl_1 mixing_bowl_empty)
    (is spatula_1 spatula_plain)
    (is sugar_1 sugar_granulated)
    (is whipped_cream_1 not-yet-made)
    (is whisk_1 whisk_plain)
    (lane bowl_1 bowl_contains_whipped_cream bowl_contains_whipped_cream)
    (lane bowl_1 bowl_empty bowl_contains_whipped_cream)
    (lane bowl_1 bowl_empty bowl_empty)
    (lane heavy_cream_1 heavy_cream_in_carton heavy_cream_in_carton)
    (lane heavy_cream_1 heavy_cream_in_carton heavy_cream_in_mixing_bowl)
    (lane heavy_cream_1 heavy_cream_in_mixing_bowl heavy_cream_in_mixing_bowl)
    (lane mixing_bowl_1 mixing_bowl_contains_heavy_cream mixing_bowl_contains_heavy_cream)
    (lane mixing_bowl_1 mixing_bowl_contains_heavy_cream mixing_bowl_contains_heavy_cream_sugar)
    (lane mixing_bowl_1 mixing_bowl_contains_heavy_cream_sugar mixing_bowl_contains_heavy_cream_sugar)
    (lane mixing_bowl_1 mixing_bowl_contains_heavy_cream_sugar mixing_bowl_contains_whipped_cream)
    (lane mixing_bowl_1 mixing_bowl_contains_whipped_cream mixing_bowl_contains_whipped_cream)
    (lane mixing_bowl_1 mixing_bowl_empty mixing_bowl_contains_heavy_cream)
    (lane mixing_bowl_1 mixing_bowl_empty mixing_bowl_empty)
    (lane spatula_1 spatula_plain spatula_plain)
    (lane sugar_1 sugar_granulated sugar_granulated)
    (lane sugar_1 sugar_granulated sugar_in_mixing_bowl)
    (lane sugar_1 sugar_in_mixing_bowl sugar_in_mixing_bowl)
    (lane whipped_cream_1 not-yet-made whipped_cream_in_mixing_bowl_whipped)
    (lane whipped_cream_1 whipped_cream_in_bowl_whipped whipped_cream_in_bowl_whipped)
    (lane whipped_cream_1 whipped_cream_in_mixing_bowl_whipped whipped_cream_in_bowl_whipped)
    (lane whipped_cream_1 whipped_cream_in_mixing_bowl_whipped whipped_cream_in_mixing_bowl_whipped)
    (lane whisk_1 whisk_plain whisk_plain)
    (occupied spatula_plain)
    (occupied whisk_plain)
    (together bowl_1 whipped_cream_1)
    (together heavy_cream_1 mixing_bowl_1)
    (together mixing_bowl_1 heavy_cream_1)
    (together mixing_bowl_1 sugar_1)
    (together mixing_bowl_1 whipped_cream_1)
    (together sugar_1 mixing_bowl_1)
    (together whipped_cream_1 bowl_1)
    (together whipped_cream_1 mixing_bowl_1)
  )
  (:goal (and
    (goal-reached)
  ))
)
