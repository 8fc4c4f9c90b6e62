; foon2pddl, encoding tree, level 3: 11 of 101 units after relevance pruning
; goal: whipped cream (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-tree-19d2f7e4)
  (:requirements :strips)
  (:predicates
    (baking_powder_in_mixing_bowl)  ; baking powder (in [mixing bowl])
    (baking_powder_powder)  ; baking powder (powder)
    (bowl_contains_whipped_cream)  ; bowl (contains {whipped cream})
    (bowl_empty)  ; bowl (empty)
    (electric_mixer_off)  ; electric mixer (off)
    (electric_mixer_off_with_mixing_bowl)  ; electric mixer (off, with [mixing bowl])
    (electric_mixer_on_with_mixing_bowl)  ; electric mixer (on, with [mixing bowl])
    (flour_in_mixing_bowl)  ; flour (in [mixing bowl])
    (flour_powder)  ; flour (powder)
    (heavy_cream_in_carton)  ; heavy cream (in [carton])
    (heavy_cream_in_mixing_bowl)  ; heavy cream (in [mixing bowl])
    (mixing_bowl_attached_to_electric_mixer_contains_heavy_cream_sugar)  ; mixing bowl (attached to [electric mixer], contains {heavy cream, sugar})
    (mixing_bowl_attached_to_electric_mixer_contains_whipped_cream)  ; mixing bowl (attached to [electric mixer], contains {whipped cream})
    (mixing_bowl_contains_baking_powder_flour_salt_sugar)  ; mixing bowl (contains {baking powder, flour, salt, sugar})
    (mixing_bowl_contains_flour)  ; mixing bowl (contains {flour})
    (mixing_bowl_contains_heavy_cream)  ; mixing bowl (contains {heavy cream})
    (mixing_bowl_contains_heavy_cream_sugar)  ; mixing bowl (contains {heavy cream, sugar})
    (mixing_bowl_contains_whipped_cream)  ; mixing bowl (contains {whipped cream})
    (mixing_bowl_empty)  ; mixing bowl (empty)
    (salt_granulated)  ; salt (granulated)
    (salt_in_mixing_bowl)  ; salt (in [mixing bowl])
    (spatula)  ; spatula
    (sugar_granulated)  ; sugar (granulated)
    (sugar_in_mixing_bowl)  ; sugar (in [mixing bowl])
    (whipped_cream_in_bowl_whipped)  ; whipped cream (in [bowl], whipped)
    (whipped_cream_in_mixing_bowl_whipped)  ; whipped cream (in [mixing bowl], whipped)
    (whisk)  ; whisk
  )

  (:action pour_u9
    ; unit 9: pour from 02-whipped_cream.foon:3, 09-fruit_salad.foon:164
    ; pour: mixing bowl (empty), heavy cream (in [carton]) -> mixing bowl (contains {heavy cream}), heavy cream (in [mixing bowl])
    :parameters ()
    :precondition (and
      (heavy_cream_in_carton)
      (mixing_bowl_empty)
    )
    :effect (and
      (heavy_cream_in_mixing_bowl)
      (mixing_bowl_contains_heavy_cream)
    )
  )

  (:action pour_u10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters ()
    :precondition (and
      (mixing_bowl_contains_heavy_cream)
      (sugar_granulated)
    )
    :effect (and
      (mixing_bowl_contains_heavy_cream_sugar)
      (sugar_in_mixing_bowl)
    )
  )

  (:action attach_u11
    ; unit 11: attach from 02-whipped_cream.foon:23
    ; attach: mixing bowl (contains {heavy cream, sugar}), electric mixer (off) -> mixing bowl (attached to [electric mixer], contains {heavy cream, sugar}), electric mixer (off, with [mixing bowl])
    :parameters ()
    :precondition (and
      (electric_mixer_off)
      (mixing_bowl_contains_heavy_cream_sugar)
    )
    :effect (and
      (electric_mixer_off_with_mixing_bowl)
      (mixing_bowl_attached_to_electric_mixer_contains_heavy_cream_sugar)
    )
  )

  (:action turn_on_u12
    ; unit 12: turn on from 02-whipped_cream.foon:35
    ; turn on: electric mixer (off, with [mixing bowl]) -> electric mixer (on, with [mixing bowl])
    :parameters ()
    :precondition (and
      (electric_mixer_off_with_mixing_bowl)
    )
    :effect (and
      (electric_mixer_on_with_mixing_bowl)
    )
  )

  (:action mix_u13
    ; unit 13: mix from 02-whipped_cream.foon:43
    ; mix: electric mixer (on, with [mixing bowl]), mixing bowl (attached to [electric mixer], contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]) -> electric mixer (on, with [mixing bowl]), mixing bowl (at...
    :parameters ()
    :precondition (and
      (electric_mixer_on_with_mixing_bowl)
      (heavy_cream_in_mixing_bowl)
      (mixing_bowl_attached_to_electric_mixer_contains_heavy_cream_sugar)
      (sugar_in_mixing_bowl)
    )
    :effect (and
      (electric_mixer_on_with_mixing_bowl)
      (mixing_bowl_attached_to_electric_mixer_contains_whipped_cream)
      (whipped_cream_in_mixing_bowl_whipped)
    )
  )

  (:action turn_off_u14
    ; unit 14: turn off from 02-whipped_cream.foon:64
    ; turn off: electric mixer (on, with [mixing bowl]) -> electric mixer (off, with [mixing bowl])
    :parameters ()
    :precondition (and
      (electric_mixer_on_with_mixing_bowl)
    )
    :effect (and
      (electric_mixer_off_with_mixing_bowl)
    )
  )

  (:action detach_u15
    ; unit 15: detach from 02-whipped_cream.foon:72
    ; detach: electric mixer (off, with [mixing bowl]), mixing bowl (attached to [electric mixer], contains {whipped cream}) -> electric mixer (off), mixing bowl (contains {whipped cream})
    :parameters ()
    :precondition (and
      (electric_mixer_off_with_mixing_bowl)
      (mixing_bowl_attached_to_electric_mixer_contains_whipped_cream)
    )
    :effect (and
      (electric_mixer_off)
      (mixing_bowl_contains_whipped_cream)
    )
  )

  (:action scoop_u16
    ; unit 16: scoop from 02-whipped_cream.foon:84
    ; scoop: mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), spatula, bowl (empty) -> bowl (contains {whipped cream}), whipped cream (in [bowl], whipped), spatula
    :parameters ()
    :precondition (and
      (bowl_empty)
      (mixing_bowl_contains_whipped_cream)
      (spatula)
      (whipped_cream_in_mixing_bowl_whipped)
    )
    :effect (and
      (bowl_contains_whipped_cream)
      (spatula)
      (whipped_cream_in_bowl_whipped)
    )
  )

  (:action pour_u29
    ; unit 29: pour from 04-pancakes.foon:3
    ; pour: mixing bowl (empty), flour (powder) -> mixing bowl (contains {flour}), flour (in [mixing bowl])
    :parameters ()
    :precondition (and
      (flour_powder)
      (mixing_bowl_empty)
    )
    :effect (and
      (flour_in_mixing_bowl)
      (mixing_bowl_contains_flour)
    )
  )

  (:action pour_u30
    ; unit 30: pour* from 04-pancakes.foon:13
    ; pour: mixing bowl (contains {flour}), baking powder (powder), sugar (granulated), salt (granulated) -> mixing bowl (contains {baking powder, flour, salt, sugar}), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixi...
    :parameters ()
    :precondition (and
      (baking_powder_powder)
      (mixing_bowl_contains_flour)
      (salt_granulated)
      (sugar_granulated)
    )
    :effect (and
      (baking_powder_in_mixing_bowl)
      (mixing_bowl_contains_baking_powder_flour_salt_sugar)
      (salt_in_mixing_bowl)
      (sugar_in_mixing_bowl)
    )
  )

  (:action whisk_u99
    ; unit 99: whisk from 09-fruit_salad.foon:184
    ; whisk: mixing bowl (contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]), whisk -> mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), whisk
    :parameters ()
    :precondition (and
      (heavy_cream_in_mixing_bowl)
      (mixing_bowl_contains_heavy_cream_sugar)
      (sugar_in_mixing_bowl)
      (whisk)
    )
    :effect (and
      (mixing_bowl_contains_whipped_cream)
      (whipped_cream_in_mixing_bowl_whipped)
      (whisk)
    )
  )
)
