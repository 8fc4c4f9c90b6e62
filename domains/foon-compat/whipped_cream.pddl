; foon2pddl, encoding foon-compat, level 3: 11 of 101 units after relevance pruning
; goal: whipped cream (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain universal_foon-ff25cfc1)
  (:requirements :strips :typing)
  (:types
    object_node - object
  )
  (:constants
    baking_powder_in_mixing_bowl - object_node
    baking_powder_powder - object_node
    bowl_contains_whipped_cream - object_node
    bowl_empty - object_node
    electric_mixer_off - object_node
    electric_mixer_off_with_mixing_bowl - object_node
    electric_mixer_on_with_mixing_bowl - object_node
    flour_in_mixing_bowl - object_node
    flour_powder - object_node
    heavy_cream_in_carton - object_node
    heavy_cream_in_mixing_bowl - object_node
    mixing_bowl_attached_to_electric_mixer_contains_heavy_cream_sugar - object_node
    mixing_bowl_attached_to_electric_mixer_contains_whipped_cream - object_node
    mixing_bowl_contains_baking_powder_flour_salt_sugar - object_node
    mixing_bowl_contains_flour - object_node
    mixing_bowl_contains_heavy_cream - object_node
    mixing_bowl_contains_heavy_cream_sugar - object_node
    mixing_bowl_contains_whipped_cream - object_node
    mixing_bowl_empty - object_node
    salt_granulated - object_node
    salt_in_mixing_bowl - object_node
    spatula - object_node
    sugar_granulated - object_node
    sugar_in_mixing_bowl - object_node
    whipped_cream_in_bowl_whipped - object_node
    whipped_cream_in_mixing_bowl_whipped - object_node
    whisk - object_node
  )
  (:predicates
    (is_available ?obj - object_node)  ; the object node is available
  )

  (:action functional_unit_9
    ; unit 9: pour from 02-whipped_cream.foon:3, 09-fruit_salad.foon:164
    ; pour: mixing bowl (empty), heavy cream (in [carton]) -> mixing bowl (contains {heavy cream}), heavy cream (in [mixing bowl])
    :parameters ()
    :precondition (and
      (is_available heavy_cream_in_carton)
      (is_available mixing_bowl_empty)
    )
    :effect (and
      (is_available heavy_cream_in_mixing_bowl)
      (is_available mixing_bowl_contains_heavy_cream)
    )
  )

  (:action functional_unit_10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters ()
    :precondition (and
      (is_available mixing_bowl_contains_heavy_cream)
      (is_available sugar_granulated)
    )
    :effect (and
      (is_available mixing_bowl_contains_heavy_cream_sugar)
      (is_available sugar_in_mixing_bowl)
    )
  )

  (:action functional_unit_11
    ; unit 11: attach from 02-whipped_cream.foon:23
    ; attach: mixing bowl (contains {heavy cream, sugar}), electric mixer (off) -> mixing bowl (attached to [electric mixer], contains {heavy cream, sugar}), electric mixer (off, with [mixing bowl])
    :parameters ()
    :precondition (and
      (is_available electric_mixer_off)
      (is_available mixing_bowl_contains_heavy_cream_sugar)
    )
    :effect (and
      (is_available electric_mixer_off_with_mixing_bowl)
      (is_available mixing_bowl_attached_to_electric_mixer_contains_heavy_cream_sugar)
    )
  )

  (:action functional_unit_12
    ; unit 12: turn on from 02-whipped_cream.foon:35
    ; turn on: electric mixer (off, with [mixing bowl]) -> electric mixer (on, with [mixing bowl])
    :parameters ()
    :precondition (and
      (is_available electric_mixer_off_with_mixing_bowl)
    )
    :effect (and
      (is_available electric_mixer_on_with_mixing_bowl)
    )
  )

  (:action functional_unit_13
    ; unit 13: mix from 02-whipped_cream.foon:43
    ; mix: electric mixer (on, with [mixing bowl]), mixing bowl (attached to [electric mixer], contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]) -> electric mixer (on, with [mixing bowl]), mixing bowl (at...
    :parameters ()
    :precondition (and
      (is_available electric_mixer_on_with_mixing_bowl)
      (is_available heavy_cream_in_mixing_bowl)
      (is_available mixing_bowl_attached_to_electric_mixer_contains_heavy_cream_sugar)
      (is_available sugar_in_mixing_bowl)
    )
    :effect (and
      (is_available electric_mixer_on_with_mixing_bowl)
      (is_available mixing_bowl_attached_to_electric_mixer_contains_whipped_cream)
      (is_available whipped_cream_in_mixing_bowl_whipped)
    )
  )

  (:action functional_unit_14
    ; unit 14: turn off from 02-whipped_cream.foon:64
    ; turn off: electric mixer (on, with [mixing bowl]) -> electric mixer (off, with [mixing bowl])
    :parameters ()
    :precondition (and
      (is_available electric_mixer_on_with_mixing_bowl)
    )
    :effect (and
      (is_available electric_mixer_off_with_mixing_bowl)
    )
  )

  (:action functional_unit_15
    ; unit 15: detach from 02-whipped_cream.foon:72
    ; detach: electric mixer (off, with [mixing bowl]), mixing bowl (attached to [electric mixer], contains {whipped cream}) -> electric mixer (off), mixing bowl (contains {whipped cream})
    :parameters ()
    :precondition (and
      (is_available electric_mixer_off_with_mixing_bowl)
      (is_available mixing_bowl_attached_to_electric_mixer_contains_whipped_cream)
    )
    :effect (and
      (is_available electric_mixer_off)
      (is_available mixing_bowl_contains_whipped_cream)
    )
  )

  (:action functional_unit_16
    ; unit 16: scoop from 02-whipped_cream.foon:84
    ; scoop: mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), spatula, bowl (empty) -> bowl (contains {whipped cream}), whipped cream (in [bowl], whipped), spatula
    :parameters ()
    :precondition (and
      (is_available bowl_empty)
      (is_available mixing_bowl_contains_whipped_cream)
      (is_available spatula)
      (is_available whipped_cream_in_mixing_bowl_whipped)
    )
    :effect (and
      (is_available bowl_contains_whipped_cream)
      (is_available spatula)
      (is_available whipped_cream_in_bowl_whipped)
    )
  )

  (:action functional_unit_29
    ; unit 29: pour from 04-pancakes.foon:3
    ; pour: mixing bowl (empty), flour (powder) -> mixing bowl (contains {flour}), flour (in [mixing bowl])
    :parameters ()
    :precondition (and
      (is_available flour_powder)
      (is_available mixing_bowl_empty)
    )
    :effect (and
      (is_available flour_in_mixing_bowl)
      (is_available mixing_bowl_contains_flour)
    )
  )

  (:action functional_unit_30
    ; unit 30: pour* from 04-pancakes.foon:13
    ; pour: mixing bowl (contains {flour}), baking powder (powder), sugar (granulated), salt (granulated) -> mixing bowl (contains {baking powder, flour, salt, sugar}), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixi...
    :parameters ()
    :precondition (and
      (is_available baking_powder_powder)
      (is_available mixing_bowl_contains_flour)
      (is_available salt_granulated)
      (is_available sugar_granulated)
    )
    :effect (and
      (is_available baking_powder_in_mixing_bowl)
      (is_available mixing_bowl_contains_baking_powder_flour_salt_sugar)
      (is_available salt_in_mixing_bowl)
      (is_available sugar_in_mixing_bowl)
    )
  )

  (:action functional_unit_99
    ; unit 99: whisk from 09-fruit_salad.foon:184
    ; whisk: mixing bowl (contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]), whisk -> mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), whisk
    :parameters ()
    :precondition (and
      (is_available heavy_cream_in_mixing_bowl)
      (is_available mixing_bowl_contains_heavy_cream_sugar)
      (is_available sugar_in_mixing_bowl)
      (is_available whisk)
    )
    :effect (and
      (is_available mixing_bowl_contains_whipped_cream)
      (is_available whipped_cream_in_mixing_bowl_whipped)
      (is_available whisk)
    )
  )
)
