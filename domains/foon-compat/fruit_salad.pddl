; foon2pddl, encoding foon-compat, level 3: 29 of 101 units after relevance pruning
; goal: fruit salad (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain universal_foon-3715f6aa)
  (:requirements :strips :typing)
  (:types
    object_node - object
  )
  (:constants
    avocado_halved_on_cutting_board - object_node
    avocado_in_bowl_mashed - object_node
    avocado_in_bowl_scooped - object_node
    avocado_on_cutting_board_whole - object_node
    avocado_whole - object_node
    baking_powder_in_mixing_bowl - object_node
    baking_powder_powder - object_node
    banana_in_bowl_sliced - object_node
    banana_on_cutting_board_peeled - object_node
    banana_on_cutting_board_sliced - object_node
    banana_peeled - object_node
    banana_whole - object_node
    bowl_contains_avocado - object_node
    bowl_contains_avocado_lime_juice - object_node
    bowl_contains_banana_honey_lime_juice_strawberry - object_node
    bowl_contains_banana_lime_juice_strawberry - object_node
    bowl_contains_banana_strawberry - object_node
    bowl_contains_fruit_salad - object_node
    bowl_contains_fruit_salad_whipped_cream - object_node
    bowl_contains_strawberry - object_node
    bowl_empty - object_node
    cutting_board_contains_avocado - object_node
    cutting_board_contains_banana - object_node
    cutting_board_contains_lime - object_node
    cutting_board_contains_strawberry - object_node
    cutting_board_empty - object_node
    electric_mixer_off - object_node
    electric_mixer_off_with_mixing_bowl - object_node
    electric_mixer_on_with_mixing_bowl - object_node
    flour_in_mixing_bowl - object_node
    flour_powder - object_node
    fork - object_node
    fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl - object_node
    fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped__831a7d6d - object_node
    heavy_cream_in_carton - object_node
    heavy_cream_in_mixing_bowl - object_node
    honey_in_bowl - object_node
    honey_in_jar - object_node
    juicer_contains_lime_juice - object_node
    juicer_empty - object_node
    knife - object_node
    lime_halved_on_cutting_board - object_node
    lime_on_cutting_board_whole - object_node
    lime_squeezed - object_node
    lime_whole - object_node
    lime_juice_in_bowl - object_node
    lime_juice_in_juicer - object_node
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
    spoon - object_node
    strawberry_in_bowl_sliced - object_node
    strawberry_on_cutting_board_sliced - object_node
    strawberry_on_cutting_board_whole - object_node
    strawberry_whole - object_node
    sugar_granulated - object_node
    sugar_in_mixing_bowl - object_node
    whipped_cream_in_mixing_bowl_whipped - object_node
    whipped_cream_on_fruit_salad_whipped - object_node
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

  (:action functional_unit_63
    ; unit 63: pick-and-place from 07-guacamole.foon:3
    ; pick-and-place: cutting board (empty), avocado (whole) -> cutting board (contains {avocado}), avocado (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (is_available avocado_whole)
      (is_available cutting_board_empty)
    )
    :effect (and
      (is_available avocado_on_cutting_board_whole)
      (is_available cutting_board_contains_avocado)
    )
  )

  (:action functional_unit_64
    ; unit 64: cut from 07-guacamole.foon:14
    ; cut: cutting board (contains {avocado}), avocado (on [cutting board], whole), knife -> cutting board (contains {avocado}), avocado (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (is_available avocado_on_cutting_board_whole)
      (is_available cutting_board_contains_avocado)
      (is_available knife)
    )
    :effect (and
      (is_available avocado_halved_on_cutting_board)
      (is_available cutting_board_contains_avocado)
      (is_available knife)
    )
  )

  (:action functional_unit_65
    ; unit 65: scoop from 07-guacamole.foon:28
    ; scoop: avocado (halved, on [cutting board]), spoon, bowl (empty) -> bowl (contains {avocado}), avocado (in [bowl], scooped), spoon
    :parameters ()
    :precondition (and
      (is_available avocado_halved_on_cutting_board)
      (is_available bowl_empty)
      (is_available spoon)
    )
    :effect (and
      (is_available avocado_in_bowl_scooped)
      (is_available bowl_contains_avocado)
      (is_available spoon)
    )
  )

  (:action functional_unit_66
    ; unit 66: mash from 07-guacamole.foon:42
    ; mash: avocado (in [bowl], scooped), fork -> avocado (in [bowl], mashed), fork
    :parameters ()
    :precondition (and
      (is_available avocado_in_bowl_scooped)
      (is_available fork)
    )
    :effect (and
      (is_available avocado_in_bowl_mashed)
      (is_available fork)
    )
  )

  (:action functional_unit_67
    ; unit 67: pick-and-place from 07-guacamole.foon:52, 09-fruit_salad.foon:83
    ; pick-and-place: cutting board (empty), lime (whole) -> cutting board (contains {lime}), lime (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (is_available cutting_board_empty)
      (is_available lime_whole)
    )
    :effect (and
      (is_available cutting_board_contains_lime)
      (is_available lime_on_cutting_board_whole)
    )
  )

  (:action functional_unit_68
    ; unit 68: cut from 07-guacamole.foon:63, 09-fruit_salad.foon:94
    ; cut: cutting board (contains {lime}), lime (on [cutting board], whole), knife -> cutting board (contains {lime}), lime (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (is_available cutting_board_contains_lime)
      (is_available knife)
      (is_available lime_on_cutting_board_whole)
    )
    :effect (and
      (is_available cutting_board_contains_lime)
      (is_available knife)
      (is_available lime_halved_on_cutting_board)
    )
  )

  (:action functional_unit_69
    ; unit 69: squeeze from 07-guacamole.foon:77, 09-fruit_salad.foon:108
    ; squeeze: lime (halved, on [cutting board]), juicer (empty) -> lime (squeezed), juicer (contains {lime juice}), lime juice (in [juicer])
    :parameters ()
    :precondition (and
      (is_available juicer_empty)
      (is_available lime_halved_on_cutting_board)
    )
    :effect (and
      (is_available juicer_contains_lime_juice)
      (is_available lime_squeezed)
      (is_available lime_juice_in_juicer)
    )
  )

  (:action functional_unit_70
    ; unit 70: pour from 07-guacamole.foon:90
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {avocado}), avocado (in [bowl], mashed) -> bowl (contains {avocado, lime juice}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (is_available avocado_in_bowl_mashed)
      (is_available bowl_contains_avocado)
      (is_available juicer_contains_lime_juice)
      (is_available lime_juice_in_juicer)
    )
    :effect (and
      (is_available bowl_contains_avocado_lime_juice)
      (is_available lime_juice_in_bowl)
    )
  )

  (:action functional_unit_89
    ; unit 89: pick-and-place from 09-fruit_salad.foon:3
    ; pick-and-place: cutting board (empty), strawberry (whole) -> cutting board (contains {strawberry}), strawberry (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (is_available cutting_board_empty)
      (is_available strawberry_whole)
    )
    :effect (and
      (is_available cutting_board_contains_strawberry)
      (is_available strawberry_on_cutting_board_whole)
    )
  )

  (:action functional_unit_90
    ; unit 90: slice from 09-fruit_salad.foon:14
    ; slice: cutting board (contains {strawberry}), strawberry (on [cutting board], whole), knife -> cutting board (contains {strawberry}), strawberry (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (is_available cutting_board_contains_strawberry)
      (is_available knife)
      (is_available strawberry_on_cutting_board_whole)
    )
    :effect (and
      (is_available cutting_board_contains_strawberry)
      (is_available knife)
      (is_available strawberry_on_cutting_board_sliced)
    )
  )

  (:action functional_unit_91
    ; unit 91: peel from 09-fruit_salad.foon:28
    ; peel: banana (whole) -> banana (peeled)
    :parameters ()
    :precondition (and
      (is_available banana_whole)
    )
    :effect (and
      (is_available banana_peeled)
    )
  )

  (:action functional_unit_92
    ; unit 92: pick-and-place from 09-fruit_salad.foon:34
    ; pick-and-place: cutting board (empty), banana (peeled) -> cutting board (contains {banana}), banana (on [cutting board], peeled)
    :parameters ()
    :precondition (and
      (is_available banana_peeled)
      (is_available cutting_board_empty)
    )
    :effect (and
      (is_available banana_on_cutting_board_peeled)
      (is_available cutting_board_contains_banana)
    )
  )

  (:action functional_unit_93
    ; unit 93: slice from 09-fruit_salad.foon:45
    ; slice: cutting board (contains {banana}), banana (on [cutting board], peeled), knife -> cutting board (contains {banana}), banana (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (is_available banana_on_cutting_board_peeled)
      (is_available cutting_board_contains_banana)
      (is_available knife)
    )
    :effect (and
      (is_available banana_on_cutting_board_sliced)
      (is_available cutting_board_contains_banana)
      (is_available knife)
    )
  )

  (:action functional_unit_94
    ; unit 94: pick-and-place from 09-fruit_salad.foon:59
    ; pick-and-place: bowl (empty), strawberry (on [cutting board], sliced) -> bowl (contains {strawberry}), strawberry (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (is_available bowl_empty)
      (is_available strawberry_on_cutting_board_sliced)
    )
    :effect (and
      (is_available bowl_contains_strawberry)
      (is_available strawberry_in_bowl_sliced)
    )
  )

  (:action functional_unit_95
    ; unit 95: pick-and-place from 09-fruit_salad.foon:71
    ; pick-and-place: bowl (contains {strawberry}), banana (on [cutting board], sliced) -> bowl (contains {banana, strawberry}), banana (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (is_available banana_on_cutting_board_sliced)
      (is_available bowl_contains_strawberry)
    )
    :effect (and
      (is_available banana_in_bowl_sliced)
      (is_available bowl_contains_banana_strawberry)
    )
  )

  (:action functional_unit_96
    ; unit 96: pour from 09-fruit_salad.foon:121
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {banana, strawberry}) -> bowl (contains {banana, lime juice, strawberry}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_banana_strawberry)
      (is_available juicer_contains_lime_juice)
      (is_available lime_juice_in_juicer)
    )
    :effect (and
      (is_available bowl_contains_banana_lime_juice_strawberry)
      (is_available lime_juice_in_bowl)
    )
  )

  (:action functional_unit_97
    ; unit 97: pour from 09-fruit_salad.foon:133
    ; pour: bowl (contains {banana, lime juice, strawberry}), honey (in [jar]) -> bowl (contains {banana, honey, lime juice, strawberry}), honey (in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_banana_lime_juice_strawberry)
      (is_available honey_in_jar)
    )
    :effect (and
      (is_available bowl_contains_banana_honey_lime_juice_strawberry)
      (is_available honey_in_bowl)
    )
  )

  (:action functional_unit_98
    ; unit 98: mix from 09-fruit_salad.foon:143
    ; mix: bowl (contains {banana, honey, lime juice, strawberry}), strawberry (in [bowl], sliced), banana (in [bowl], sliced), lime juice (in [bowl]), honey (in [bowl]), spoon -> bowl (contains {fruit salad}), fruit salad (contains {banana, h...
    :parameters ()
    :precondition (and
      (is_available banana_in_bowl_sliced)
      (is_available bowl_contains_banana_honey_lime_juice_strawberry)
      (is_available honey_in_bowl)
      (is_available lime_juice_in_bowl)
      (is_available spoon)
      (is_available strawberry_in_bowl_sliced)
    )
    :effect (and
      (is_available bowl_contains_fruit_salad)
      (is_available fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl)
      (is_available spoon)
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

  (:action functional_unit_100
    ; unit 100: scoop from 09-fruit_salad.foon:199
    ; scoop: bowl (contains {fruit salad}), fruit salad (contains {banana, honey, lime juice, strawberry}, in [bowl]), mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), spoon -> bowl (contains {fruit salad, whi...
    :parameters ()
    :precondition (and
      (is_available bowl_contains_fruit_salad)
      (is_available fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl)
      (is_available mixing_bowl_contains_whipped_cream)
      (is_available spoon)
      (is_available whipped_cream_in_mixing_bowl_whipped)
    )
    :effect (and
      (is_available bowl_contains_fruit_salad_whipped_cream)
      (is_available fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped__831a7d6d)
      (is_available spoon)
      (is_available whipped_cream_on_fruit_salad_whipped)
    )
  )
)
