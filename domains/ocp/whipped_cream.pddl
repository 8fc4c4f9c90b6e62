; foon2pddl, encoding ocp, level 3: 6 of 101 units after relevance pruning
; goal: whipped cream (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-ocp-e3e18b07)
  (:requirements :strips)
  (:constants
    air
    baking_powder
    bowl
    carton
    electric_mixer
    heavy_cream
    mixing_bowl
    salt
    spatula
    sugar
    table
    whipped_cream
    whisk
  )
  (:predicates
    (in ?h ?x)  ; in ?h is ?x (?x is in ?h; air: ?h is empty)
    (on ?h ?x)  ; on ?h is ?x (?x is on ?h)
    (under ?x ?h)  ; under ?x is ?h (?x is on or in ?h)
  )

  (:action pour_heavy_cream_9
    ; unit 9: pour from 02-whipped_cream.foon:3, 09-fruit_salad.foon:164
    ; pour: mixing bowl (empty), heavy cream (in [carton]) -> mixing bowl (contains {heavy cream}), heavy cream (in [mixing bowl])
    :parameters ()
    :precondition (and
      (in mixing_bowl air)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in carton heavy_cream)
      (under heavy_cream carton)
    )
    :effect (and
      (in mixing_bowl heavy_cream)
      (under heavy_cream mixing_bowl)
      (in carton heavy_cream)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (not (in mixing_bowl air))
    )
  )

  (:action pour_sugar_10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters ()
    :precondition (and
      (under mixing_bowl table)
      (on table mixing_bowl)
      (under sugar table)
      (on table sugar)
    )
    :effect (and
      (in mixing_bowl sugar)
      (under sugar mixing_bowl)
      (under mixing_bowl table)
      (on table mixing_bowl)
    )
  )

  (:action mix_ingredients_13
    ; unit 13: mix from 02-whipped_cream.foon:43
    ; mix: electric mixer (on, with [mixing bowl]), mixing bowl (attached to [electric mixer], contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]) -> electric mixer (on, with [mixing bowl]), mixing bowl (at...
    :parameters ()
    :precondition (and
      (under electric_mixer table)
      (on table electric_mixer)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in mixing_bowl heavy_cream)
      (under heavy_cream mixing_bowl)
      (in mixing_bowl sugar)
      (under sugar mixing_bowl)
    )
    :effect (and
      (in mixing_bowl whipped_cream)
      (under whipped_cream mixing_bowl)
      (under heavy_cream mixing_bowl)
      (under sugar mixing_bowl)
      (under electric_mixer table)
      (on table electric_mixer)
      (under mixing_bowl table)
      (on table mixing_bowl)
    )
  )

  (:action scoop_bowl_16
    ; unit 16: scoop from 02-whipped_cream.foon:84
    ; scoop: mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), spatula, bowl (empty) -> bowl (contains {whipped cream}), whipped cream (in [bowl], whipped), spatula
    :parameters ()
    :precondition (and
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in mixing_bowl whipped_cream)
      (under whipped_cream mixing_bowl)
      (under spatula table)
      (on table spatula)
      (in bowl air)
      (under bowl table)
      (on table bowl)
    )
    :effect (and
      (in bowl whipped_cream)
      (under whipped_cream bowl)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in mixing_bowl whipped_cream)
      (under spatula table)
      (on table spatula)
      (under bowl table)
      (on table bowl)
      (not (in bowl air))
    )
  )

  (:action pour_baking_powder_30
    ; unit 30: pour* from 04-pancakes.foon:13
    ; pour: mixing bowl (contains {flour}), baking powder (powder), sugar (granulated), salt (granulated) -> mixing bowl (contains {baking powder, flour, salt, sugar}), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixi...
    :parameters ()
    :precondition (and
      (under mixing_bowl table)
      (on table mixing_bowl)
      (under baking_powder table)
      (on table baking_powder)
      (under sugar table)
      (on table sugar)
      (under salt table)
      (on table salt)
    )
    :effect (and
      (in mixing_bowl baking_powder)
      (under baking_powder mixing_bowl)
      (in mixing_bowl sugar)
      (under sugar mixing_bowl)
      (in mixing_bowl salt)
      (under salt mixing_bowl)
      (under mixing_bowl table)
      (on table mixing_bowl)
    )
  )

  (:action whisk_99
    ; unit 99: whisk from 09-fruit_salad.foon:184
    ; whisk: mixing bowl (contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]), whisk -> mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), whisk
    :parameters ()
    :precondition (and
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in mixing_bowl heavy_cream)
      (under heavy_cream mixing_bowl)
      (in mixing_bowl sugar)
      (under sugar mixing_bowl)
      (under whisk table)
      (on table whisk)
    )
    :effect (and
      (in mixing_bowl whipped_cream)
      (under whipped_cream mixing_bowl)
      (under heavy_cream mixing_bowl)
      (under sugar mixing_bowl)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (under whisk table)
      (on table whisk)
    )
  )
)
