; foon2pddl, encoding instances, level 3: 25 of 101 units after relevance pruning
; goal: whipped cream (3 candidate nodes)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 21 (avocado 1, baking powder 1, banana 1, bowl 1, cutting board 1, electric mixer 1, flour 1, fork 1, heavy cream 1, honey 1, juicer 1, knife 1, lime 1, mixing bowl 1, salt 1, spatula 1, spoon 1, strawberry 1, sugar 1, whipped cream 1, whisk 1)
(define (domain foon-instances)
  (:requirements :strips :typing)
  (:types
    physical-object - object
    object-state - object
    avocado - physical-object
    baking_powder - physical-object
    banana - physical-object
    bowl - physical-object
    cutting_board - physical-object
    electric_mixer - physical-object
    flour - physical-object
    fork - physical-object
    heavy_cream - physical-object
    honey - physical-object
    juicer - physical-object
    knife - physical-object
    lime - physical-object
    mixing_bowl - physical-object
    salt - physical-object
    spatula - physical-object
    spoon - physical-object
    strawberry - physical-object
    sugar - physical-object
    whipped_cream - physical-object
    whisk - physical-object
  )
  (:constants
    not-yet-made - object-state
    avocado_halved_on_cutting_board - object-state
    avocado_in_bowl_mashed - object-state
    avocado_in_bowl_scooped - object-state
    avocado_on_cutting_board_whole - object-state
    avocado_whole - object-state
    baking_powder_in_mixing_bowl - object-state
    baking_powder_powder - object-state
    banana_in_bowl_sliced - object-state
    banana_on_cutting_board_peeled - object-state
    banana_on_cutting_board_sliced - object-state
    banana_peeled - object-state
    banana_whole - object-state
    bowl_contains_avocado - object-state
    bowl_contains_banana_honey_lime_juice_strawberry - object-state
    bowl_contains_banana_lime_juice_strawberry - object-state
    bowl_contains_banana_strawberry - object-state
    bowl_contains_strawberry - object-state
    bowl_contains_whipped_cream - object-state
    bowl_empty - object-state
    cutting_board_contains_avocado - object-state
    cutting_board_contains_banana - object-state
    cutting_board_contains_lime - object-state
    cutting_board_contains_strawberry - object-state
    cutting_board_empty - object-state
    electric_mixer_off - object-state
    electric_mixer_off_with_mixing_bowl - object-state
    electric_mixer_on_with_mixing_bowl - object-state
    flour_in_mixing_bowl - object-state
    flour_powder - object-state
    fork_plain - object-state
    heavy_cream_in_carton - object-state
    heavy_cream_in_mixing_bowl - object-state
    honey_in_bowl - object-state
    honey_in_jar - object-state
    juicer_empty - object-state
    knife_plain - object-state
    lime_halved_on_cutting_board - object-state
    lime_on_cutting_board_whole - object-state
    lime_whole - object-state
    mixing_bowl_attached_to_electric_mixer_contains_heavy_cream_sugar - object-state
    mixing_bowl_attached_to_electric_mixer_contains_whipped_cream - object-state
    mixing_bowl_contains_baking_powder_flour_salt_sugar - object-state
    mixing_bowl_contains_flour - object-state
    mixing_bowl_contains_heavy_cream - object-state
    mixing_bowl_contains_heavy_cream_sugar - object-state
    mixing_bowl_contains_whipped_cream - object-state
    mixing_bowl_empty - object-state
    salt_granulated - object-state
    salt_in_mixing_bowl - object-state
    spatula_plain - object-state
    spoon_plain - object-state
    strawberry_in_bowl_sliced - object-state
    strawberry_on_cutting_board_sliced - object-state
    strawberry_on_cutting_board_whole - object-state
    strawberry_whole - object-state
    sugar_granulated - object-state
    sugar_in_mixing_bowl - object-state
    whipped_cream_in_bowl_whipped - object-state
    whipped_cream_in_mixing_bowl_whipped - object-state
    whipped_cream_on_fruit_salad_whipped - object-state
    whisk_plain - object-state
  )
  (:predicates
    (is ?x - physical-object ?s - object-state)  ; ?x is in the state of FOON node ?s
    (occupied ?s - object-state)  ; some instance is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
  )

  (:action pour_u9
    ; unit 9: pour from 02-whipped_cream.foon:3, 09-fruit_salad.foon:164
    ; pour: mixing bowl (empty), heavy cream (in [carton]) -> mixing bowl (contains {heavy cream}), heavy cream (in [mixing bowl])
    :parameters (?mixing_bowl - mixing_bowl ?heavy_cream - heavy_cream)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_empty)
      (is ?heavy_cream heavy_cream_in_carton)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream)
      (is ?heavy_cream heavy_cream_in_mixing_bowl)
      (occupied heavy_cream_in_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_empty))
      (not (is ?heavy_cream heavy_cream_in_carton))
    )
  )

  (:action pour_u10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters (?mixing_bowl - mixing_bowl ?sugar - sugar)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream)
      (is ?sugar sugar_granulated)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar)
      (is ?sugar sugar_in_mixing_bowl)
      (occupied sugar_in_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_contains_heavy_cream))
      (not (is ?sugar sugar_granulated))
    )
  )

  (:action attach_u11
    ; unit 11: attach from 02-whipped_cream.foon:23
    ; attach: mixing bowl (contains {heavy cream, sugar}), electric mixer (off) -> mixing bowl (attached to [electric mixer], contains {heavy cream, sugar}), electric mixer (off, with [mixing bowl])
    :parameters (?mixing_bowl - mixing_bowl ?electric_mixer - electric_mixer)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar)
      (is ?electric_mixer electric_mixer_off)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_attached_to_electric_mixer_contains_heavy_cream_sugar)
      (is ?electric_mixer electric_mixer_off_with_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar))
      (not (is ?electric_mixer electric_mixer_off))
    )
  )

  (:action turn_on_u12
    ; unit 12: turn on from 02-whipped_cream.foon:35
    ; turn on: electric mixer (off, with [mixing bowl]) -> electric mixer (on, with [mixing bowl])
    :parameters (?electric_mixer - electric_mixer)
    :precondition (and
      (is ?electric_mixer electric_mixer_off_with_mixing_bowl)
    )
    :effect (and
      (is ?electric_mixer electric_mixer_on_with_mixing_bowl)
      (not (is ?electric_mixer electric_mixer_off_with_mixing_bowl))
    )
  )

  (:action mix_u13
    ; unit 13: mix from 02-whipped_cream.foon:43
    ; mix: electric mixer (on, with [mixing bowl]), mixing bowl (attached to [electric mixer], contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]) -> electric mixer (on, with [mixing bowl]), mixing bowl (at...
    :parameters (?electric_mixer - electric_mixer ?mixing_bowl - mixing_bowl ?whipped_cream - whipped_cream)
    :precondition (and
      (is ?electric_mixer electric_mixer_on_with_mixing_bowl)
      (is ?mixing_bowl mixing_bowl_attached_to_electric_mixer_contains_heavy_cream_sugar)
      (occupied heavy_cream_in_mixing_bowl)
      (occupied sugar_in_mixing_bowl)
      (is ?whipped_cream not-yet-made)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_attached_to_electric_mixer_contains_whipped_cream)
      (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped)
      (not (is ?mixing_bowl mixing_bowl_attached_to_electric_mixer_contains_heavy_cream_sugar))
      (not (is ?whipped_cream not-yet-made))
    )
  )

  (:action turn_off_u14
    ; unit 14: turn off from 02-whipped_cream.foon:64
    ; turn off: electric mixer (on, with [mixing bowl]) -> electric mixer (off, with [mixing bowl])
    :parameters (?electric_mixer - electric_mixer)
    :precondition (and
      (is ?electric_mixer electric_mixer_on_with_mixing_bowl)
    )
    :effect (and
      (is ?electric_mixer electric_mixer_off_with_mixing_bowl)
      (not (is ?electric_mixer electric_mixer_on_with_mixing_bowl))
    )
  )

  (:action detach_u15
    ; unit 15: detach from 02-whipped_cream.foon:72
    ; detach: electric mixer (off, with [mixing bowl]), mixing bowl (attached to [electric mixer], contains {whipped cream}) -> electric mixer (off), mixing bowl (contains {whipped cream})
    :parameters (?electric_mixer - electric_mixer ?mixing_bowl - mixing_bowl)
    :precondition (and
      (is ?electric_mixer electric_mixer_off_with_mixing_bowl)
      (is ?mixing_bowl mixing_bowl_attached_to_electric_mixer_contains_whipped_cream)
    )
    :effect (and
      (is ?electric_mixer electric_mixer_off)
      (is ?mixing_bowl mixing_bowl_contains_whipped_cream)
      (occupied mixing_bowl_contains_whipped_cream)
      (not (is ?electric_mixer electric_mixer_off_with_mixing_bowl))
      (not (is ?mixing_bowl mixing_bowl_attached_to_electric_mixer_contains_whipped_cream))
    )
  )

  (:action scoop_u16
    ; unit 16: scoop from 02-whipped_cream.foon:84
    ; scoop: mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), spatula, bowl (empty) -> bowl (contains {whipped cream}), whipped cream (in [bowl], whipped), spatula
    :parameters (?whipped_cream - whipped_cream ?bowl - bowl)
    :precondition (and
      (occupied mixing_bowl_contains_whipped_cream)
      (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped)
      (occupied spatula_plain)
      (is ?bowl bowl_empty)
    )
    :effect (and
      (is ?whipped_cream whipped_cream_in_bowl_whipped)
      (occupied whipped_cream_in_bowl_whipped)
      (is ?bowl bowl_contains_whipped_cream)
      (occupied bowl_contains_whipped_cream)
      (not (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped))
      (not (is ?bowl bowl_empty))
    )
  )

  (:action pour_u29
    ; unit 29: pour from 04-pancakes.foon:3
    ; pour: mixing bowl (empty), flour (powder) -> mixing bowl (contains {flour}), flour (in [mixing bowl])
    :parameters (?mixing_bowl - mixing_bowl ?flour - flour)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_empty)
      (is ?flour flour_powder)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_flour)
      (is ?flour flour_in_mixing_bowl)
      (occupied flour_in_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_empty))
      (not (is ?flour flour_powder))
    )
  )

  (:action pour_u30
    ; unit 30: pour* from 04-pancakes.foon:13
    ; pour: mixing bowl (contains {flour}), baking powder (powder), sugar (granulated), salt (granulated) -> mixing bowl (contains {baking powder, flour, salt, sugar}), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixi...
    :parameters (?mixing_bowl - mixing_bowl ?baking_powder - baking_powder ?sugar - sugar ?salt - salt)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_flour)
      (is ?baking_powder baking_powder_powder)
      (is ?sugar sugar_granulated)
      (is ?salt salt_granulated)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_baking_powder_flour_salt_sugar)
      (occupied mixing_bowl_contains_baking_powder_flour_salt_sugar)
      (is ?baking_powder baking_powder_in_mixing_bowl)
      (occupied baking_powder_in_mixing_bowl)
      (is ?sugar sugar_in_mixing_bowl)
      (occupied sugar_in_mixing_bowl)
      (is ?salt salt_in_mixing_bowl)
      (occupied salt_in_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_contains_flour))
      (not (is ?baking_powder baking_powder_powder))
      (not (is ?sugar sugar_granulated))
      (not (is ?salt salt_granulated))
    )
  )

  (:action pick-and-place_u63
    ; unit 63: pick-and-place from 07-guacamole.foon:3
    ; pick-and-place: cutting board (empty), avocado (whole) -> cutting board (contains {avocado}), avocado (on [cutting board], whole)
    :parameters (?cutting_board - cutting_board ?avocado - avocado)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?avocado avocado_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_avocado)
      (occupied cutting_board_contains_avocado)
      (is ?avocado avocado_on_cutting_board_whole)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?avocado avocado_whole))
    )
  )

  (:action cut_u64
    ; unit 64: cut from 07-guacamole.foon:14
    ; cut: cutting board (contains {avocado}), avocado (on [cutting board], whole), knife -> cutting board (contains {avocado}), avocado (halved, on [cutting board]), knife
    :parameters (?avocado - avocado)
    :precondition (and
      (occupied cutting_board_contains_avocado)
      (is ?avocado avocado_on_cutting_board_whole)
      (occupied knife_plain)
    )
    :effect (and
      (is ?avocado avocado_halved_on_cutting_board)
      (not (is ?avocado avocado_on_cutting_board_whole))
    )
  )

  (:action scoop_u65
    ; unit 65: scoop from 07-guacamole.foon:28
    ; scoop: avocado (halved, on [cutting board]), spoon, bowl (empty) -> bowl (contains {avocado}), avocado (in [bowl], scooped), spoon
    :parameters (?avocado - avocado ?bowl - bowl)
    :precondition (and
      (is ?avocado avocado_halved_on_cutting_board)
      (occupied spoon_plain)
      (is ?bowl bowl_empty)
    )
    :effect (and
      (is ?avocado avocado_in_bowl_scooped)
      (is ?bowl bowl_contains_avocado)
      (occupied bowl_contains_avocado)
      (not (is ?avocado avocado_halved_on_cutting_board))
      (not (is ?bowl bowl_empty))
    )
  )

  (:action mash_u66
    ; unit 66: mash from 07-guacamole.foon:42
    ; mash: avocado (in [bowl], scooped), fork -> avocado (in [bowl], mashed), fork
    :parameters (?avocado - avocado)
    :precondition (and
      (is ?avocado avocado_in_bowl_scooped)
      (occupied fork_plain)
    )
    :effect (and
      (is ?avocado avocado_in_bowl_mashed)
      (occupied avocado_in_bowl_mashed)
      (not (is ?avocado avocado_in_bowl_scooped))
    )
  )

  (:action pick-and-place_u67
    ; unit 67: pick-and-place from 07-guacamole.foon:52, 09-fruit_salad.foon:83
    ; pick-and-place: cutting board (empty), lime (whole) -> cutting board (contains {lime}), lime (on [cutting board], whole)
    :parameters (?cutting_board - cutting_board ?lime - lime)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?lime lime_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_lime)
      (occupied cutting_board_contains_lime)
      (is ?lime lime_on_cutting_board_whole)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?lime lime_whole))
    )
  )

  (:action cut_u68
    ; unit 68: cut from 07-guacamole.foon:63, 09-fruit_salad.foon:94
    ; cut: cutting board (contains {lime}), lime (on [cutting board], whole), knife -> cutting board (contains {lime}), lime (halved, on [cutting board]), knife
    :parameters (?lime - lime)
    :precondition (and
      (occupied cutting_board_contains_lime)
      (is ?lime lime_on_cutting_board_whole)
      (occupied knife_plain)
    )
    :effect (and
      (is ?lime lime_halved_on_cutting_board)
      (occupied lime_halved_on_cutting_board)
      (not (is ?lime lime_on_cutting_board_whole))
    )
  )

  (:action pick-and-place_u89
    ; unit 89: pick-and-place from 09-fruit_salad.foon:3
    ; pick-and-place: cutting board (empty), strawberry (whole) -> cutting board (contains {strawberry}), strawberry (on [cutting board], whole)
    :parameters (?cutting_board - cutting_board ?strawberry - strawberry)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?strawberry strawberry_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_strawberry)
      (occupied cutting_board_contains_strawberry)
      (is ?strawberry strawberry_on_cutting_board_whole)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?strawberry strawberry_whole))
    )
  )

  (:action slice_u90
    ; unit 90: slice from 09-fruit_salad.foon:14
    ; slice: cutting board (contains {strawberry}), strawberry (on [cutting board], whole), knife -> cutting board (contains {strawberry}), strawberry (on [cutting board], sliced), knife
    :parameters (?strawberry - strawberry)
    :precondition (and
      (occupied cutting_board_contains_strawberry)
      (is ?strawberry strawberry_on_cutting_board_whole)
      (occupied knife_plain)
    )
    :effect (and
      (is ?strawberry strawberry_on_cutting_board_sliced)
      (not (is ?strawberry strawberry_on_cutting_board_whole))
    )
  )

  (:action peel_u91
    ; unit 91: peel from 09-fruit_salad.foon:28
    ; peel: banana (whole) -> banana (peeled)
    :parameters (?banana - banana)
    :precondition (and
      (is ?banana banana_whole)
    )
    :effect (and
      (is ?banana banana_peeled)
      (not (is ?banana banana_whole))
    )
  )

  (:action pick-and-place_u92
    ; unit 92: pick-and-place from 09-fruit_salad.foon:34
    ; pick-and-place: cutting board (empty), banana (peeled) -> cutting board (contains {banana}), banana (on [cutting board], peeled)
    :parameters (?cutting_board - cutting_board ?banana - banana)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?banana banana_peeled)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_banana)
      (occupied cutting_board_contains_banana)
      (is ?banana banana_on_cutting_board_peeled)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?banana banana_peeled))
    )
  )

  (:action slice_u93
    ; unit 93: slice from 09-fruit_salad.foon:45
    ; slice: cutting board (contains {banana}), banana (on [cutting board], peeled), knife -> cutting board (contains {banana}), banana (on [cutting board], sliced), knife
    :parameters (?banana - banana)
    :precondition (and
      (occupied cutting_board_contains_banana)
      (is ?banana banana_on_cutting_board_peeled)
      (occupied knife_plain)
    )
    :effect (and
      (is ?banana banana_on_cutting_board_sliced)
      (not (is ?banana banana_on_cutting_board_peeled))
    )
  )

  (:action pick-and-place_u94
    ; unit 94: pick-and-place from 09-fruit_salad.foon:59
    ; pick-and-place: bowl (empty), strawberry (on [cutting board], sliced) -> bowl (contains {strawberry}), strawberry (in [bowl], sliced)
    :parameters (?bowl - bowl ?strawberry - strawberry)
    :precondition (and
      (is ?bowl bowl_empty)
      (is ?strawberry strawberry_on_cutting_board_sliced)
    )
    :effect (and
      (is ?bowl bowl_contains_strawberry)
      (is ?strawberry strawberry_in_bowl_sliced)
      (occupied strawberry_in_bowl_sliced)
      (not (is ?bowl bowl_empty))
      (not (is ?strawberry strawberry_on_cutting_board_sliced))
    )
  )

  (:action pick-and-place_u95
    ; unit 95: pick-and-place from 09-fruit_salad.foon:71
    ; pick-and-place: bowl (contains {strawberry}), banana (on [cutting board], sliced) -> bowl (contains {banana, strawberry}), banana (in [bowl], sliced)
    :parameters (?bowl - bowl ?banana - banana)
    :precondition (and
      (is ?bowl bowl_contains_strawberry)
      (is ?banana banana_on_cutting_board_sliced)
    )
    :effect (and
      (is ?bowl bowl_contains_banana_strawberry)
      (occupied bowl_contains_banana_strawberry)
      (is ?banana banana_in_bowl_sliced)
      (occupied banana_in_bowl_sliced)
      (not (is ?bowl bowl_contains_strawberry))
      (not (is ?banana banana_on_cutting_board_sliced))
    )
  )

  (:action pour_u97
    ; unit 97: pour from 09-fruit_salad.foon:133
    ; pour: bowl (contains {banana, lime juice, strawberry}), honey (in [jar]) -> bowl (contains {banana, honey, lime juice, strawberry}), honey (in [bowl])
    :parameters (?bowl - bowl ?honey - honey)
    :precondition (and
      (is ?bowl bowl_contains_banana_lime_juice_strawberry)
      (is ?honey honey_in_jar)
    )
    :effect (and
      (is ?bowl bowl_contains_banana_honey_lime_juice_strawberry)
      (occupied bowl_contains_banana_honey_lime_juice_strawberry)
      (is ?honey honey_in_bowl)
      (occupied honey_in_bowl)
      (not (is ?bowl bowl_contains_banana_lime_juice_strawberry))
      (not (is ?honey honey_in_jar))
    )
  )

  (:action whisk_u99
    ; unit 99: whisk from 09-fruit_salad.foon:184
    ; whisk: mixing bowl (contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]), whisk -> mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), whisk
    :parameters (?mixing_bowl - mixing_bowl ?whipped_cream - whipped_cream)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar)
      (occupied heavy_cream_in_mixing_bowl)
      (occupied sugar_in_mixing_bowl)
      (occupied whisk_plain)
      (is ?whipped_cream not-yet-made)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_whipped_cream)
      (occupied mixing_bowl_contains_whipped_cream)
      (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped)
      (not (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar))
      (not (is ?whipped_cream not-yet-made))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: whipped cream (in [bowl], whipped)
    :parameters ()
    :precondition (and
      (occupied whipped_cream_in_bowl_whipped)
    )
    :effect (and
      (goal-reached)
    )
  )

  (:action reach-goal-2
    ; goal candidate 2: whipped cream (in [mixing bowl], whipped)
    :parameters (?x - whipped_cream)
    :precondition (and
      (is ?x whipped_cream_in_mixing_bowl_whipped)
    )
    :effect (and
      (goal-reached)
    )
  )

  (:action reach-goal-3
    ; goal candidate 3: whipped cream (on [fruit salad], whipped)
    :parameters ()
    :precondition (and
      (occupied whipped_cream_on_fruit_salad_whipped)
    )
    :effect (and
      (goal-reached)
    )
  )
)
