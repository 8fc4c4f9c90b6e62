; foon2pddl, encoding foon-compat, level 3: 37 of 101 units after relevance pruning
; goal: guacamole (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain universal_foon-d251c74d)
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
    banana_in_bowl_sliced - object_node
    banana_on_cutting_board_peeled - object_node
    banana_on_cutting_board_sliced - object_node
    banana_peeled - object_node
    banana_whole - object_node
    black_pepper_ground - object_node
    black_pepper_in_bowl - object_node
    bowl_contains_avocado - object_node
    bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato - object_node
    bowl_contains_avocado_cilantro_lime_juice_onion_tomato - object_node
    bowl_contains_avocado_lime_juice - object_node
    bowl_contains_avocado_lime_juice_onion - object_node
    bowl_contains_avocado_lime_juice_onion_tomato - object_node
    bowl_contains_banana_lime_juice_strawberry - object_node
    bowl_contains_banana_strawberry - object_node
    bowl_contains_black_pepper_egg_milk_salt - object_node
    bowl_contains_cucumber - object_node
    bowl_contains_cucumber_tomato - object_node
    bowl_contains_egg - object_node
    bowl_contains_egg_milk - object_node
    bowl_contains_guacamole - object_node
    bowl_contains_strawberry - object_node
    bowl_empty - object_node
    cilantro_chopped_in_bowl - object_node
    cilantro_chopped_on_cutting_board - object_node
    cilantro_fresh - object_node
    cilantro_fresh_on_cutting_board - object_node
    cucumber_in_bowl_sliced - object_node
    cucumber_on_cutting_board_sliced - object_node
    cucumber_on_cutting_board_whole - object_node
    cucumber_whole - object_node
    cutting_board_contains_avocado - object_node
    cutting_board_contains_banana - object_node
    cutting_board_contains_cilantro - object_node
    cutting_board_contains_cucumber - object_node
    cutting_board_contains_lime - object_node
    cutting_board_contains_onion - object_node
    cutting_board_contains_strawberry - object_node
    cutting_board_contains_tomato - object_node
    cutting_board_empty - object_node
    egg_beaten_in_bowl - object_node
    egg_cracked_in_bowl - object_node
    egg_whole - object_node
    fork - object_node
    guacamole_contains_avocado_cilantro_lime_juice_onion_salt_tomato_in_bowl - object_node
    juicer_contains_lime_juice - object_node
    juicer_empty - object_node
    knife - object_node
    lime_halved_on_cutting_board - object_node
    lime_on_cutting_board_whole - object_node
    lime_squeezed - object_node
    lime_whole - object_node
    lime_juice_in_bowl - object_node
    lime_juice_in_juicer - object_node
    milk_in_bowl - object_node
    milk_in_carton - object_node
    onion_chopped_in_bowl - object_node
    onion_chopped_on_cutting_board - object_node
    onion_on_cutting_board_peeled - object_node
    onion_on_cutting_board_whole - object_node
    onion_whole - object_node
    salt_granulated - object_node
    salt_in_bowl - object_node
    spoon - object_node
    strawberry_in_bowl_sliced - object_node
    strawberry_on_cutting_board_sliced - object_node
    strawberry_on_cutting_board_whole - object_node
    strawberry_whole - object_node
    tomato_chopped_in_bowl - object_node
    tomato_chopped_on_cutting_board - object_node
    tomato_on_cutting_board_whole - object_node
    tomato_whole - object_node
    whisk - object_node
  )
  (:predicates
    (is_available ?obj - object_node)  ; the object node is available
  )

  (:action functional_unit_17
    ; unit 17: crack from 03-scrambled_eggs.foon:3, 05-french_toast.foon:3
    ; crack: bowl (empty), egg (whole) -> bowl (contains {egg}), egg (cracked, in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_empty)
      (is_available egg_whole)
    )
    :effect (and
      (is_available bowl_contains_egg)
      (is_available egg_cracked_in_bowl)
    )
  )

  (:action functional_unit_18
    ; unit 18: beat from 03-scrambled_eggs.foon:14
    ; beat: egg (cracked, in [bowl]), whisk -> egg (beaten, in [bowl]), whisk
    :parameters ()
    :precondition (and
      (is_available egg_cracked_in_bowl)
      (is_available whisk)
    )
    :effect (and
      (is_available egg_beaten_in_bowl)
      (is_available whisk)
    )
  )

  (:action functional_unit_19
    ; unit 19: pour from 03-scrambled_eggs.foon:24, 05-french_toast.foon:24
    ; pour: bowl (contains {egg}), egg (beaten, in [bowl]), milk (in [carton]) -> bowl (contains {egg, milk}), milk (in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_egg)
      (is_available egg_beaten_in_bowl)
      (is_available milk_in_carton)
    )
    :effect (and
      (is_available bowl_contains_egg_milk)
      (is_available milk_in_bowl)
    )
  )

  (:action functional_unit_20
    ; unit 20: sprinkle from 03-scrambled_eggs.foon:37
    ; sprinkle: bowl (contains {egg, milk}), salt (granulated), black pepper (ground) -> bowl (contains {black pepper, egg, milk, salt}), salt (in [bowl]), black pepper (in [bowl])
    :parameters ()
    :precondition (and
      (is_available black_pepper_ground)
      (is_available bowl_contains_egg_milk)
      (is_available salt_granulated)
    )
    :effect (and
      (is_available black_pepper_in_bowl)
      (is_available bowl_contains_black_pepper_egg_milk_salt)
      (is_available salt_in_bowl)
    )
  )

  (:action functional_unit_39
    ; unit 39: beat from 05-french_toast.foon:14
    ; beat: egg (cracked, in [bowl]), fork -> egg (beaten, in [bowl]), fork
    :parameters ()
    :precondition (and
      (is_available egg_cracked_in_bowl)
      (is_available fork)
    )
    :effect (and
      (is_available egg_beaten_in_bowl)
      (is_available fork)
    )
  )

  (:action functional_unit_47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (is_available cutting_board_empty)
      (is_available onion_whole)
    )
    :effect (and
      (is_available cutting_board_contains_onion)
      (is_available onion_on_cutting_board_whole)
    )
  )

  (:action functional_unit_48
    ; unit 48: peel from 06-tomato_soup.foon:14, 07-guacamole.foon:116, 08-greek_salad.foon:64
    ; peel: cutting board (contains {onion}), onion (on [cutting board], whole), knife -> cutting board (contains {onion}), onion (on [cutting board], peeled), knife
    :parameters ()
    :precondition (and
      (is_available cutting_board_contains_onion)
      (is_available knife)
      (is_available onion_on_cutting_board_whole)
    )
    :effect (and
      (is_available cutting_board_contains_onion)
      (is_available knife)
      (is_available onion_on_cutting_board_peeled)
    )
  )

  (:action functional_unit_49
    ; unit 49: chop from 06-tomato_soup.foon:28, 07-guacamole.foon:130
    ; chop: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (is_available cutting_board_contains_onion)
      (is_available knife)
      (is_available onion_on_cutting_board_peeled)
    )
    :effect (and
      (is_available cutting_board_contains_onion)
      (is_available knife)
      (is_available onion_chopped_on_cutting_board)
    )
  )

  (:action functional_unit_50
    ; unit 50: pick-and-place from 06-tomato_soup.foon:42, 07-guacamole.foon:156, 08-greek_salad.foon:28
    ; pick-and-place: cutting board (empty), tomato (whole) -> cutting board (contains {tomato}), tomato (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (is_available cutting_board_empty)
      (is_available tomato_whole)
    )
    :effect (and
      (is_available cutting_board_contains_tomato)
      (is_available tomato_on_cutting_board_whole)
    )
  )

  (:action functional_unit_51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (is_available cutting_board_contains_tomato)
      (is_available knife)
      (is_available tomato_on_cutting_board_whole)
    )
    :effect (and
      (is_available cutting_board_contains_tomato)
      (is_available knife)
      (is_available tomato_chopped_on_cutting_board)
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

  (:action functional_unit_71
    ; unit 71: pick-and-place from 07-guacamole.foon:144
    ; pick-and-place: bowl (contains {avocado, lime juice}), onion (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion}), onion (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_avocado_lime_juice)
      (is_available onion_chopped_on_cutting_board)
    )
    :effect (and
      (is_available bowl_contains_avocado_lime_juice_onion)
      (is_available onion_chopped_in_bowl)
    )
  )

  (:action functional_unit_72
    ; unit 72: pick-and-place from 07-guacamole.foon:181
    ; pick-and-place: bowl (contains {avocado, lime juice, onion}), tomato (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion, tomato}), tomato (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_avocado_lime_juice_onion)
      (is_available tomato_chopped_on_cutting_board)
    )
    :effect (and
      (is_available bowl_contains_avocado_lime_juice_onion_tomato)
      (is_available tomato_chopped_in_bowl)
    )
  )

  (:action functional_unit_73
    ; unit 73: pick-and-place from 07-guacamole.foon:193
    ; pick-and-place: cutting board (empty), cilantro (fresh) -> cutting board (contains {cilantro}), cilantro (fresh, on [cutting board])
    :parameters ()
    :precondition (and
      (is_available cilantro_fresh)
      (is_available cutting_board_empty)
    )
    :effect (and
      (is_available cilantro_fresh_on_cutting_board)
      (is_available cutting_board_contains_cilantro)
    )
  )

  (:action functional_unit_74
    ; unit 74: chop from 07-guacamole.foon:204
    ; chop: cutting board (contains {cilantro}), cilantro (fresh, on [cutting board]), knife -> cutting board (contains {cilantro}), cilantro (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (is_available cilantro_fresh_on_cutting_board)
      (is_available cutting_board_contains_cilantro)
      (is_available knife)
    )
    :effect (and
      (is_available cilantro_chopped_on_cutting_board)
      (is_available cutting_board_contains_cilantro)
      (is_available knife)
    )
  )

  (:action functional_unit_75
    ; unit 75: pick-and-place from 07-guacamole.foon:218
    ; pick-and-place: bowl (contains {avocado, lime juice, onion, tomato}), cilantro (chopped, on [cutting board]) -> bowl (contains {avocado, cilantro, lime juice, onion, tomato}), cilantro (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_avocado_lime_juice_onion_tomato)
      (is_available cilantro_chopped_on_cutting_board)
    )
    :effect (and
      (is_available bowl_contains_avocado_cilantro_lime_juice_onion_tomato)
      (is_available cilantro_chopped_in_bowl)
    )
  )

  (:action functional_unit_76
    ; unit 76: sprinkle from 07-guacamole.foon:230
    ; sprinkle: bowl (contains {avocado, cilantro, lime juice, onion, tomato}), salt (granulated) -> bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato}), salt (in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_avocado_cilantro_lime_juice_onion_tomato)
      (is_available salt_granulated)
    )
    :effect (and
      (is_available bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato)
      (is_available salt_in_bowl)
    )
  )

  (:action functional_unit_77
    ; unit 77: mix from 07-guacamole.foon:240
    ; mix: bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato}), avocado (in [bowl], mashed), lime juice (in [bowl]), onion (chopped, in [bowl]), tomato (chopped, in [bowl]), cilantro (chopped, in [bowl]), salt (in [bowl]), for...
    :parameters ()
    :precondition (and
      (is_available avocado_in_bowl_mashed)
      (is_available bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato)
      (is_available cilantro_chopped_in_bowl)
      (is_available fork)
      (is_available lime_juice_in_bowl)
      (is_available onion_chopped_in_bowl)
      (is_available salt_in_bowl)
      (is_available tomato_chopped_in_bowl)
    )
    :effect (and
      (is_available bowl_contains_guacamole)
      (is_available fork)
      (is_available guacamole_contains_avocado_cilantro_lime_juice_onion_salt_tomato_in_bowl)
    )
  )

  (:action functional_unit_78
    ; unit 78: pick-and-place from 08-greek_salad.foon:3
    ; pick-and-place: cutting board (empty), cucumber (whole) -> cutting board (contains {cucumber}), cucumber (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (is_available cucumber_whole)
      (is_available cutting_board_empty)
    )
    :effect (and
      (is_available cucumber_on_cutting_board_whole)
      (is_available cutting_board_contains_cucumber)
    )
  )

  (:action functional_unit_79
    ; unit 79: slice from 08-greek_salad.foon:14
    ; slice: cutting board (contains {cucumber}), cucumber (on [cutting board], whole), knife -> cutting board (contains {cucumber}), cucumber (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (is_available cucumber_on_cutting_board_whole)
      (is_available cutting_board_contains_cucumber)
      (is_available knife)
    )
    :effect (and
      (is_available cucumber_on_cutting_board_sliced)
      (is_available cutting_board_contains_cucumber)
      (is_available knife)
    )
  )

  (:action functional_unit_81
    ; unit 81: pick-and-place from 08-greek_salad.foon:92
    ; pick-and-place: bowl (empty), cucumber (on [cutting board], sliced) -> bowl (contains {cucumber}), cucumber (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (is_available bowl_empty)
      (is_available cucumber_on_cutting_board_sliced)
    )
    :effect (and
      (is_available bowl_contains_cucumber)
      (is_available cucumber_in_bowl_sliced)
    )
  )

  (:action functional_unit_82
    ; unit 82: pick-and-place from 08-greek_salad.foon:104
    ; pick-and-place: bowl (contains {cucumber}), tomato (chopped, on [cutting board]) -> bowl (contains {cucumber, tomato}), tomato (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_cucumber)
      (is_available tomato_chopped_on_cutting_board)
    )
    :effect (and
      (is_available bowl_contains_cucumber_tomato)
      (is_available tomato_chopped_in_bowl)
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
)
