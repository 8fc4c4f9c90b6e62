; foon2pddl, encoding tree, level 3: 29 of 101 units after relevance pruning
; goal: fruit salad (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-tree-3fdfcac0)
  (:requirements :strips)
  (:predicates
    (avocado_halved_on_cutting_board)  ; avocado (halved, on [cutting board])
    (avocado_in_bowl_mashed)  ; avocado (in [bowl], mashed)
    (avocado_in_bowl_scooped)  ; avocado (in [bowl], scooped)
    (avocado_on_cutting_board_whole)  ; avocado (on [cutting board], whole)
    (avocado_whole)  ; avocado (whole)
    (baking_powder_in_mixing_bowl)  ; baking powder (in [mixing bowl])
    (baking_powder_powder)  ; baking powder (powder)
    (banana_in_bowl_sliced)  ; banana (in [bowl], sliced)
    (banana_on_cutting_board_peeled)  ; banana (on [cutting board], peeled)
    (banana_on_cutting_board_sliced)  ; banana (on [cutting board], sliced)
    (banana_peeled)  ; banana (peeled)
    (banana_whole)  ; banana (whole)
    (bowl_contains_avocado)  ; bowl (contains {avocado})
    (bowl_contains_avocado_lime_juice)  ; bowl (contains {avocado, lime juice})
    (bowl_contains_banana_honey_lime_juice_strawberry)  ; bowl (contains {banana, honey, lime juice, strawberry})
    (bowl_contains_banana_lime_juice_strawberry)  ; bowl (contains {banana, lime juice, strawberry})
    (bowl_contains_banana_strawberry)  ; bowl (contains {banana, strawberry})
    (bowl_contains_fruit_salad)  ; bowl (contains {fruit salad})
    (bowl_contains_fruit_salad_whipped_cream)  ; bowl (contains {fruit salad, whipped cream})
    (bowl_contains_strawberry)  ; bowl (contains {strawberry})
    (bowl_empty)  ; bowl (empty)
    (cutting_board_contains_avocado)  ; cutting board (contains {avocado})
    (cutting_board_contains_banana)  ; cutting board (contains {banana})
    (cutting_board_contains_lime)  ; cutting board (contains {lime})
    (cutting_board_contains_strawberry)  ; cutting board (contains {strawberry})
    (cutting_board_empty)  ; cutting board (empty)
    (electric_mixer_off)  ; electric mixer (off)
    (electric_mixer_off_with_mixing_bowl)  ; electric mixer (off, with [mixing bowl])
    (electric_mixer_on_with_mixing_bowl)  ; electric mixer (on, with [mixing bowl])
    (flour_in_mixing_bowl)  ; flour (in [mixing bowl])
    (flour_powder)  ; flour (powder)
    (fork)  ; fork
    (fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl)  ; fruit salad (contains {banana, honey, lime juice, strawberry}, in [bowl])
    (fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped__831a7d6d)  ; fruit salad (contains {banana, honey, lime juice, strawberry}, in [bowl], topped {whipped cream})
    (heavy_cream_in_carton)  ; heavy cream (in [carton])
    (heavy_cream_in_mixing_bowl)  ; heavy cream (in [mixing bowl])
    (honey_in_bowl)  ; honey (in [bowl])
    (honey_in_jar)  ; honey (in [jar])
    (juicer_contains_lime_juice)  ; juicer (contains {lime juice})
    (juicer_empty)  ; juicer (empty)
    (knife)  ; knife
    (lime_halved_on_cutting_board)  ; lime (halved, on [cutting board])
    (lime_on_cutting_board_whole)  ; lime (on [cutting board], whole)
    (lime_squeezed)  ; lime (squeezed)
    (lime_whole)  ; lime (whole)
    (lime_juice_in_bowl)  ; lime juice (in [bowl])
    (lime_juice_in_juicer)  ; lime juice (in [juicer])
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
    (spoon)  ; spoon
    (strawberry_in_bowl_sliced)  ; strawberry (in [bowl], sliced)
    (strawberry_on_cutting_board_sliced)  ; strawberry (on [cutting board], sliced)
    (strawberry_on_cutting_board_whole)  ; strawberry (on [cutting board], whole)
    (strawberry_whole)  ; strawberry (whole)
    (sugar_granulated)  ; sugar (granulated)
    (sugar_in_mixing_bowl)  ; sugar (in [mixing bowl])
    (whipped_cream_in_mixing_bowl_whipped)  ; whipped cream (in [mixing bowl], whipped)
    (whipped_cream_on_fruit_salad_whipped)  ; whipped cream (on [fruit salad], whipped)
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

  (:action pick-and-place_u63
    ; unit 63: pick-and-place from 07-guacamole.foon:3
    ; pick-and-place: cutting board (empty), avocado (whole) -> cutting board (contains {avocado}), avocado (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (avocado_whole)
      (cutting_board_empty)
    )
    :effect (and
      (avocado_on_cutting_board_whole)
      (cutting_board_contains_avocado)
    )
  )

  (:action cut_u64
    ; unit 64: cut from 07-guacamole.foon:14
    ; cut: cutting board (contains {avocado}), avocado (on [cutting board], whole), knife -> cutting board (contains {avocado}), avocado (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (avocado_on_cutting_board_whole)
      (cutting_board_contains_avocado)
      (knife)
    )
    :effect (and
      (avocado_halved_on_cutting_board)
      (cutting_board_contains_avocado)
      (knife)
    )
  )

  (:action scoop_u65
    ; unit 65: scoop from 07-guacamole.foon:28
    ; scoop: avocado (halved, on [cutting board]), spoon, bowl (empty) -> bowl (contains {avocado}), avocado (in [bowl], scooped), spoon
    :parameters ()
    :precondition (and
      (avocado_halved_on_cutting_board)
      (bowl_empty)
      (spoon)
    )
    :effect (and
      (avocado_in_bowl_scooped)
      (bowl_contains_avocado)
      (spoon)
    )
  )

  (:action mash_u66
    ; unit 66: mash from 07-guacamole.foon:42
    ; mash: avocado (in [bowl], scooped), fork -> avocado (in [bowl], mashed), fork
    :parameters ()
    :precondition (and
      (avocado_in_bowl_scooped)
      (fork)
    )
    :effect (and
      (avocado_in_bowl_mashed)
      (fork)
    )
  )

  (:action pick-and-place_u67
    ; unit 67: pick-and-place from 07-guacamole.foon:52, 09-fruit_salad.foon:83
    ; pick-and-place: cutting board (empty), lime (whole) -> cutting board (contains {lime}), lime (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (cutting_board_empty)
      (lime_whole)
    )
    :effect (and
      (cutting_board_contains_lime)
      (lime_on_cutting_board_whole)
    )
  )

  (:action cut_u68
    ; unit 68: cut from 07-guacamole.foon:63, 09-fruit_salad.foon:94
    ; cut: cutting board (contains {lime}), lime (on [cutting board], whole), knife -> cutting board (contains {lime}), lime (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (cutting_board_contains_lime)
      (knife)
      (lime_on_cutting_board_whole)
    )
    :effect (and
      (cutting_board_contains_lime)
      (knife)
      (lime_halved_on_cutting_board)
    )
  )

  (:action squeeze_u69
    ; unit 69: squeeze from 07-guacamole.foon:77, 09-fruit_salad.foon:108
    ; squeeze: lime (halved, on [cutting board]), juicer (empty) -> lime (squeezed), juicer (contains {lime juice}), lime juice (in [juicer])
    :parameters ()
    :precondition (and
      (juicer_empty)
      (lime_halved_on_cutting_board)
    )
    :effect (and
      (juicer_contains_lime_juice)
      (lime_squeezed)
      (lime_juice_in_juicer)
    )
  )

  (:action pour_u70
    ; unit 70: pour from 07-guacamole.foon:90
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {avocado}), avocado (in [bowl], mashed) -> bowl (contains {avocado, lime juice}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (avocado_in_bowl_mashed)
      (bowl_contains_avocado)
      (juicer_contains_lime_juice)
      (lime_juice_in_juicer)
    )
    :effect (and
      (bowl_contains_avocado_lime_juice)
      (lime_juice_in_bowl)
    )
  )

  (:action pick-and-place_u89
    ; unit 89: pick-and-place from 09-fruit_salad.foon:3
    ; pick-and-place: cutting board (empty), strawberry (whole) -> cutting board (contains {strawberry}), strawberry (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (cutting_board_empty)
      (strawberry_whole)
    )
    :effect (and
      (cutting_board_contains_strawberry)
      (strawberry_on_cutting_board_whole)
    )
  )

  (:action slice_u90
    ; unit 90: slice from 09-fruit_salad.foon:14
    ; slice: cutting board (contains {strawberry}), strawberry (on [cutting board], whole), knife -> cutting board (contains {strawberry}), strawberry (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (cutting_board_contains_strawberry)
      (knife)
      (strawberry_on_cutting_board_whole)
    )
    :effect (and
      (cutting_board_contains_strawberry)
      (knife)
      (strawberry_on_cutting_board_sliced)
    )
  )

  (:action peel_u91
    ; unit 91: peel from 09-fruit_salad.foon:28
    ; peel: banana (whole) -> banana (peeled)
    :parameters ()
    :precondition (and
      (banana_whole)
    )
    :effect (and
      (banana_peeled)
    )
  )

  (:action pick-and-place_u92
    ; unit 92: pick-and-place from 09-fruit_salad.foon:34
    ; pick-and-place: cutting board (empty), banana (peeled) -> cutting board (contains {banana}), banana (on [cutting board], peeled)
    :parameters ()
    :precondition (and
      (banana_peeled)
      (cutting_board_empty)
    )
    :effect (and
      (banana_on_cutting_board_peeled)
      (cutting_board_contains_banana)
    )
  )

  (:action slice_u93
    ; unit 93: slice from 09-fruit_salad.foon:45
    ; slice: cutting board (contains {banana}), banana (on [cutting board], peeled), knife -> cutting board (contains {banana}), banana (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (banana_on_cutting_board_peeled)
      (cutting_board_contains_banana)
      (knife)
    )
    :effect (and
      (banana_on_cutting_board_sliced)
      (cutting_board_contains_banana)
      (knife)
    )
  )

  (:action pick-and-place_u94
    ; unit 94: pick-and-place from 09-fruit_salad.foon:59
    ; pick-and-place: bowl (empty), strawberry (on [cutting board], sliced) -> bowl (contains {strawberry}), strawberry (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (bowl_empty)
      (strawberry_on_cutting_board_sliced)
    )
    :effect (and
      (bowl_contains_strawberry)
      (strawberry_in_bowl_sliced)
    )
  )

  (:action pick-and-place_u95
    ; unit 95: pick-and-place from 09-fruit_salad.foon:71
    ; pick-and-place: bowl (contains {strawberry}), banana (on [cutting board], sliced) -> bowl (contains {banana, strawberry}), banana (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (banana_on_cutting_board_sliced)
      (bowl_contains_strawberry)
    )
    :effect (and
      (banana_in_bowl_sliced)
      (bowl_contains_banana_strawberry)
    )
  )

  (:action pour_u96
    ; unit 96: pour from 09-fruit_salad.foon:121
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {banana, strawberry}) -> bowl (contains {banana, lime juice, strawberry}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (bowl_contains_banana_strawberry)
      (juicer_contains_lime_juice)
      (lime_juice_in_juicer)
    )
    :effect (and
      (bowl_contains_banana_lime_juice_strawberry)
      (lime_juice_in_bowl)
    )
  )

  (:action pour_u97
    ; unit 97: pour from 09-fruit_salad.foon:133
    ; pour: bowl (contains {banana, lime juice, strawberry}), honey (in [jar]) -> bowl (contains {banana, honey, lime juice, strawberry}), honey (in [bowl])
    :parameters ()
    :precondition (and
      (bowl_contains_banana_lime_juice_strawberry)
      (honey_in_jar)
    )
    :effect (and
      (bowl_contains_banana_honey_lime_juice_strawberry)
      (honey_in_bowl)
    )
  )

  (:action mix_u98
    ; unit 98: mix from 09-fruit_salad.foon:143
    ; mix: bowl (contains {banana, honey, lime juice, strawberry}), strawberry (in [bowl], sliced), banana (in [bowl], sliced), lime juice (in [bowl]), honey (in [bowl]), spoon -> bowl (contains {fruit salad}), fruit salad (contains {banana, h...
    :parameters ()
    :precondition (and
      (banana_in_bowl_sliced)
      (bowl_contains_banana_honey_lime_juice_strawberry)
      (honey_in_bowl)
      (lime_juice_in_bowl)
      (spoon)
      (strawberry_in_bowl_sliced)
    )
    :effect (and
      (bowl_contains_fruit_salad)
      (fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl)
      (spoon)
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

  (:action scoop_u100
    ; unit 100: scoop from 09-fruit_salad.foon:199
    ; scoop: bowl (contains {fruit salad}), fruit salad (contains {banana, honey, lime juice, strawberry}, in [bowl]), mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), spoon -> bowl (contains {fruit salad, whi...
    :parameters ()
    :precondition (and
      (bowl_contains_fruit_salad)
      (fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl)
      (mixing_bowl_contains_whipped_cream)
      (spoon)
      (whipped_cream_in_mixing_bowl_whipped)
    )
    :effect (and
      (bowl_contains_fruit_salad_whipped_cream)
      (fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped__831a7d6d)
      (spoon)
      (whipped_cream_on_fruit_salad_whipped)
    )
  )
)
