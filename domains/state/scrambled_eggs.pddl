; foon2pddl, encoding state, level 3: 51 of 101 units after relevance pruning
; goal: scrambled eggs (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-state-c7b2eac4)
  (:requirements :strips)
  (:constants
    avocado
    baking_powder
    banana
    black_pepper
    bowl
    butter
    carton
    cilantro
    cucumber
    cutting_board
    egg
    egg_mixture
    flour
    fork
    frying_pan
    heavy_cream
    juicer
    knife
    lime
    lime_juice
    milk
    mixing_bowl
    onion
    plate
    salt
    scrambled_eggs
    spatula
    spoon
    stove
    strawberry
    sugar
    tomato
    whisk
  )
  (:predicates
    (available ?o)  ; the object is in the kitchen or was made
    (is-beaten ?o)  ; ?o is beaten
    (is-chopped ?o)  ; ?o is chopped
    (is-cooked ?o)  ; ?o is cooked
    (is-cracked ?o)  ; ?o is cracked
    (is-empty ?o)  ; ?o is empty
    (is-fresh ?o)  ; ?o is fresh
    (is-granulated ?o)  ; ?o is granulated
    (is-ground ?o)  ; ?o is ground
    (is-halved ?o)  ; ?o is halved
    (is-mashed ?o)  ; ?o is mashed
    (is-melted ?o)  ; ?o is melted
    (is-off ?o)  ; ?o is off
    (is-on ?o)  ; ?o is on
    (is-peeled ?o)  ; ?o is peeled
    (is-powder ?o)  ; ?o is powder
    (is-scooped ?o)  ; ?o is scooped
    (is-sliced ?o)  ; ?o is sliced
    (is-solid ?o)  ; ?o is solid
    (is-squeezed ?o)  ; ?o is squeezed
    (is-whole ?o)  ; ?o is whole
    (contains ?o ?r)  ; ?o contains [?r] or {?r}
    (in ?o ?r)  ; ?o in [?r] or {?r}
    (on ?o ?r)  ; ?o on [?r] or {?r}
  )

  (:action pour_u9
    ; unit 9: pour from 02-whipped_cream.foon:3, 09-fruit_salad.foon:164
    ; pour: mixing bowl (empty), heavy cream (in [carton]) -> mixing bowl (contains {heavy cream}), heavy cream (in [mixing bowl])
    :parameters ()
    :precondition (and
      (available heavy_cream)
      (available mixing_bowl)
      (in heavy_cream carton)
      (is-empty mixing_bowl)
    )
    :effect (and
      (contains mixing_bowl heavy_cream)
      (in heavy_cream mixing_bowl)
      (not (in heavy_cream carton))
      (not (is-empty mixing_bowl))
    )
  )

  (:action pour_u10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters ()
    :precondition (and
      (available mixing_bowl)
      (available sugar)
      (contains mixing_bowl heavy_cream)
      (is-granulated sugar)
    )
    :effect (and
      (contains mixing_bowl sugar)
      (in sugar mixing_bowl)
      (not (is-granulated sugar))
    )
  )

  (:action crack_u17
    ; unit 17: crack from 03-scrambled_eggs.foon:3, 05-french_toast.foon:3
    ; crack: bowl (empty), egg (whole) -> bowl (contains {egg}), egg (cracked, in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available egg)
      (is-empty bowl)
      (is-whole egg)
    )
    :effect (and
      (contains bowl egg)
      (in egg bowl)
      (is-cracked egg)
      (not (is-empty bowl))
      (not (is-whole egg))
    )
  )

  (:action beat_u18
    ; unit 18: beat from 03-scrambled_eggs.foon:14
    ; beat: egg (cracked, in [bowl]), whisk -> egg (beaten, in [bowl]), whisk
    :parameters ()
    :precondition (and
      (available egg)
      (available whisk)
      (in egg bowl)
      (is-cracked egg)
    )
    :effect (and
      (is-beaten egg)
      (not (is-cracked egg))
    )
  )

  (:action pour_u19
    ; unit 19: pour from 03-scrambled_eggs.foon:24, 05-french_toast.foon:24
    ; pour: bowl (contains {egg}), egg (beaten, in [bowl]), milk (in [carton]) -> bowl (contains {egg, milk}), milk (in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available egg)
      (available milk)
      (contains bowl egg)
      (in egg bowl)
      (in milk carton)
      (is-beaten egg)
    )
    :effect (and
      (contains bowl milk)
      (in milk bowl)
      (not (in milk carton))
    )
  )

  (:action sprinkle_u20
    ; unit 20: sprinkle from 03-scrambled_eggs.foon:37
    ; sprinkle: bowl (contains {egg, milk}), salt (granulated), black pepper (ground) -> bowl (contains {black pepper, egg, milk, salt}), salt (in [bowl]), black pepper (in [bowl])
    :parameters ()
    :precondition (and
      (available black_pepper)
      (available bowl)
      (available salt)
      (contains bowl egg)
      (contains bowl milk)
      (is-granulated salt)
      (is-ground black_pepper)
    )
    :effect (and
      (contains bowl black_pepper)
      (contains bowl salt)
      (in black_pepper bowl)
      (in salt bowl)
      (not (is-granulated salt))
      (not (is-ground black_pepper))
    )
  )

  (:action mix_u21
    ; unit 21: mix from 03-scrambled_eggs.foon:51
    ; mix: bowl (contains {black pepper, egg, milk, salt}), egg (beaten, in [bowl]), milk (in [bowl]), salt (in [bowl]), black pepper (in [bowl]), whisk -> bowl (contains {egg mixture}), egg mixture (contains {black pepper, egg, milk, salt}, i...
    :parameters ()
    :precondition (and
      (available black_pepper)
      (available bowl)
      (available egg)
      (available milk)
      (available salt)
      (available whisk)
      (contains bowl black_pepper)
      (contains bowl egg)
      (contains bowl milk)
      (contains bowl salt)
      (in black_pepper bowl)
      (in egg bowl)
      (in milk bowl)
      (in salt bowl)
      (is-beaten egg)
    )
    :effect (and
      (available egg_mixture)
      (contains bowl egg_mixture)
      (contains egg_mixture black_pepper)
      (contains egg_mixture egg)
      (contains egg_mixture milk)
      (contains egg_mixture salt)
      (in egg_mixture bowl)
      (not (contains bowl black_pepper))
      (not (contains bowl egg))
      (not (contains bowl milk))
      (not (contains bowl salt))
    )
  )

  (:action pick-and-place_u22
    ; unit 22: pick-and-place from 03-scrambled_eggs.foon:71, 04-pancakes.foon:76, 05-french_toast.foon:83
    ; pick-and-place: frying pan (empty), stove (off) -> frying pan (empty, on [stove])
    :parameters ()
    :precondition (and
      (available frying_pan)
      (available stove)
      (is-empty frying_pan)
      (is-off stove)
    )
    :effect (and
      (on frying_pan stove)
    )
  )

  (:action turn_on_u23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters ()
    :precondition (and
      (available stove)
      (is-off stove)
    )
    :effect (and
      (is-on stove)
      (not (is-off stove))
    )
  )

  (:action pick-and-place_u24
    ; unit 24: pick-and-place from 03-scrambled_eggs.foon:86, 04-pancakes.foon:91, 05-french_toast.foon:98
    ; pick-and-place: frying pan (empty, on [stove]), butter (solid) -> frying pan (contains {butter}, on [stove]), butter (in [frying pan], solid)
    :parameters ()
    :precondition (and
      (available butter)
      (available frying_pan)
      (is-empty frying_pan)
      (is-solid butter)
      (on frying_pan stove)
    )
    :effect (and
      (contains frying_pan butter)
      (in butter frying_pan)
      (not (is-empty frying_pan))
    )
  )

  (:action melt_u25
    ; unit 25: melt from 03-scrambled_eggs.foon:99, 04-pancakes.foon:104, 05-french_toast.foon:111
    ; melt: stove (on), butter (in [frying pan], solid) -> butter (in [frying pan], melted)
    :parameters ()
    :precondition (and
      (available butter)
      (available stove)
      (in butter frying_pan)
      (is-on stove)
      (is-solid butter)
    )
    :effect (and
      (is-melted butter)
      (not (is-solid butter))
    )
  )

  (:action pour_u26
    ; unit 26: pour from 03-scrambled_eggs.foon:109
    ; pour: bowl (contains {egg mixture}), egg mixture (contains {black pepper, egg, milk, salt}, in [bowl]), frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted) -> frying pan (contains {butter, egg mixture}, on [stove...
    :parameters ()
    :precondition (and
      (available bowl)
      (available butter)
      (available egg_mixture)
      (available frying_pan)
      (contains bowl egg_mixture)
      (contains egg_mixture black_pepper)
      (contains egg_mixture egg)
      (contains egg_mixture milk)
      (contains egg_mixture salt)
      (contains frying_pan butter)
      (in butter frying_pan)
      (in egg_mixture bowl)
      (is-melted butter)
      (on frying_pan stove)
    )
    :effect (and
      (contains frying_pan egg_mixture)
      (in egg_mixture frying_pan)
      (not (in egg_mixture bowl))
    )
  )

  (:action stir_u27
    ; unit 27: stir from 03-scrambled_eggs.foon:128
    ; stir: stove (on), frying pan (contains {butter, egg mixture}, on [stove]), egg mixture (contains {black pepper, egg, milk, salt}, in [frying pan]), spatula -> frying pan (contains {scrambled eggs}, on [stove]), scrambled eggs (cooked, in...
    :parameters ()
    :precondition (and
      (available egg_mixture)
      (available frying_pan)
      (available spatula)
      (available stove)
      (contains egg_mixture black_pepper)
      (contains egg_mixture egg)
      (contains egg_mixture milk)
      (contains egg_mixture salt)
      (contains frying_pan butter)
      (contains frying_pan egg_mixture)
      (in egg_mixture frying_pan)
      (is-on stove)
      (on frying_pan stove)
    )
    :effect (and
      (available scrambled_eggs)
      (contains frying_pan scrambled_eggs)
      (in scrambled_eggs frying_pan)
      (is-cooked scrambled_eggs)
      (not (contains frying_pan butter))
      (not (contains frying_pan egg_mixture))
    )
  )

  (:action scoop_u28
    ; unit 28: scoop from 03-scrambled_eggs.foon:146
    ; scoop: frying pan (contains {scrambled eggs}, on [stove]), scrambled eggs (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {scrambled eggs}), scrambled eggs (cooked, on [plate]), spatula
    :parameters ()
    :precondition (and
      (available frying_pan)
      (available plate)
      (available scrambled_eggs)
      (available spatula)
      (contains frying_pan scrambled_eggs)
      (in scrambled_eggs frying_pan)
      (is-cooked scrambled_eggs)
      (is-empty plate)
      (on frying_pan stove)
    )
    :effect (and
      (contains plate scrambled_eggs)
      (on scrambled_eggs plate)
      (not (in scrambled_eggs frying_pan))
      (not (is-empty plate))
    )
  )

  (:action pour_u29
    ; unit 29: pour from 04-pancakes.foon:3
    ; pour: mixing bowl (empty), flour (powder) -> mixing bowl (contains {flour}), flour (in [mixing bowl])
    :parameters ()
    :precondition (and
      (available flour)
      (available mixing_bowl)
      (is-empty mixing_bowl)
      (is-powder flour)
    )
    :effect (and
      (contains mixing_bowl flour)
      (in flour mixing_bowl)
      (not (is-empty mixing_bowl))
      (not (is-powder flour))
    )
  )

  (:action pour_u30
    ; unit 30: pour* from 04-pancakes.foon:13
    ; pour: mixing bowl (contains {flour}), baking powder (powder), sugar (granulated), salt (granulated) -> mixing bowl (contains {baking powder, flour, salt, sugar}), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixi...
    :parameters ()
    :precondition (and
      (available baking_powder)
      (available mixing_bowl)
      (available salt)
      (available sugar)
      (contains mixing_bowl flour)
      (is-granulated salt)
      (is-granulated sugar)
      (is-powder baking_powder)
    )
    :effect (and
      (contains mixing_bowl baking_powder)
      (contains mixing_bowl salt)
      (contains mixing_bowl sugar)
      (in baking_powder mixing_bowl)
      (in salt mixing_bowl)
      (in sugar mixing_bowl)
      (not (is-granulated salt))
      (not (is-granulated sugar))
      (not (is-powder baking_powder))
    )
  )

  (:action crack_u31
    ; unit 31: crack from 04-pancakes.foon:31
    ; crack: mixing bowl (contains {baking powder, flour, salt, sugar}), egg (whole) -> mixing bowl (contains {baking powder, egg, flour, salt, sugar}), egg (cracked, in [mixing bowl])
    :parameters ()
    :precondition (and
      (available egg)
      (available mixing_bowl)
      (contains mixing_bowl baking_powder)
      (contains mixing_bowl flour)
      (contains mixing_bowl salt)
      (contains mixing_bowl sugar)
      (is-whole egg)
    )
    :effect (and
      (contains mixing_bowl egg)
      (in egg mixing_bowl)
      (is-cracked egg)
      (not (is-whole egg))
    )
  )

  (:action beat_u39
    ; unit 39: beat from 05-french_toast.foon:14
    ; beat: egg (cracked, in [bowl]), fork -> egg (beaten, in [bowl]), fork
    :parameters ()
    :precondition (and
      (available egg)
      (available fork)
      (in egg bowl)
      (is-cracked egg)
    )
    :effect (and
      (is-beaten egg)
      (not (is-cracked egg))
    )
  )

  (:action pick-and-place_u47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available onion)
      (is-empty cutting_board)
      (is-whole onion)
    )
    :effect (and
      (contains cutting_board onion)
      (on onion cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action peel_u48
    ; unit 48: peel from 06-tomato_soup.foon:14, 07-guacamole.foon:116, 08-greek_salad.foon:64
    ; peel: cutting board (contains {onion}), onion (on [cutting board], whole), knife -> cutting board (contains {onion}), onion (on [cutting board], peeled), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available onion)
      (contains cutting_board onion)
      (is-whole onion)
      (on onion cutting_board)
    )
    :effect (and
      (is-peeled onion)
      (not (is-whole onion))
    )
  )

  (:action chop_u49
    ; unit 49: chop from 06-tomato_soup.foon:28, 07-guacamole.foon:130
    ; chop: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available onion)
      (contains cutting_board onion)
      (is-peeled onion)
      (on onion cutting_board)
    )
    :effect (and
      (is-chopped onion)
      (not (is-peeled onion))
    )
  )

  (:action pick-and-place_u50
    ; unit 50: pick-and-place from 06-tomato_soup.foon:42, 07-guacamole.foon:156, 08-greek_salad.foon:28
    ; pick-and-place: cutting board (empty), tomato (whole) -> cutting board (contains {tomato}), tomato (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available tomato)
      (is-empty cutting_board)
      (is-whole tomato)
    )
    :effect (and
      (contains cutting_board tomato)
      (on tomato cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action chop_u51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available tomato)
      (contains cutting_board tomato)
      (is-whole tomato)
      (on tomato cutting_board)
    )
    :effect (and
      (is-chopped tomato)
      (not (is-whole tomato))
    )
  )

  (:action pick-and-place_u63
    ; unit 63: pick-and-place from 07-guacamole.foon:3
    ; pick-and-place: cutting board (empty), avocado (whole) -> cutting board (contains {avocado}), avocado (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available avocado)
      (available cutting_board)
      (is-empty cutting_board)
      (is-whole avocado)
    )
    :effect (and
      (contains cutting_board avocado)
      (on avocado cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action cut_u64
    ; unit 64: cut from 07-guacamole.foon:14
    ; cut: cutting board (contains {avocado}), avocado (on [cutting board], whole), knife -> cutting board (contains {avocado}), avocado (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (available avocado)
      (available cutting_board)
      (available knife)
      (contains cutting_board avocado)
      (is-whole avocado)
      (on avocado cutting_board)
    )
    :effect (and
      (is-halved avocado)
      (not (is-whole avocado))
    )
  )

  (:action scoop_u65
    ; unit 65: scoop from 07-guacamole.foon:28
    ; scoop: avocado (halved, on [cutting board]), spoon, bowl (empty) -> bowl (contains {avocado}), avocado (in [bowl], scooped), spoon
    :parameters ()
    :precondition (and
      (available avocado)
      (available bowl)
      (available spoon)
      (is-empty bowl)
      (is-halved avocado)
      (on avocado cutting_board)
    )
    :effect (and
      (contains bowl avocado)
      (in avocado bowl)
      (is-scooped avocado)
      (not (is-empty bowl))
      (not (is-halved avocado))
      (not (on avocado cutting_board))
    )
  )

  (:action mash_u66
    ; unit 66: mash from 07-guacamole.foon:42
    ; mash: avocado (in [bowl], scooped), fork -> avocado (in [bowl], mashed), fork
    :parameters ()
    :precondition (and
      (available avocado)
      (available fork)
      (in avocado bowl)
      (is-scooped avocado)
    )
    :effect (and
      (is-mashed avocado)
      (not (is-scooped avocado))
    )
  )

  (:action pick-and-place_u67
    ; unit 67: pick-and-place from 07-guacamole.foon:52, 09-fruit_salad.foon:83
    ; pick-and-place: cutting board (empty), lime (whole) -> cutting board (contains {lime}), lime (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available lime)
      (is-empty cutting_board)
      (is-whole lime)
    )
    :effect (and
      (contains cutting_board lime)
      (on lime cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action cut_u68
    ; unit 68: cut from 07-guacamole.foon:63, 09-fruit_salad.foon:94
    ; cut: cutting board (contains {lime}), lime (on [cutting board], whole), knife -> cutting board (contains {lime}), lime (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available lime)
      (contains cutting_board lime)
      (is-whole lime)
      (on lime cutting_board)
    )
    :effect (and
      (is-halved lime)
      (not (is-whole lime))
    )
  )

  (:action squeeze_u69
    ; unit 69: squeeze from 07-guacamole.foon:77, 09-fruit_salad.foon:108
    ; squeeze: lime (halved, on [cutting board]), juicer (empty) -> lime (squeezed), juicer (contains {lime juice}), lime juice (in [juicer])
    :parameters ()
    :precondition (and
      (available juicer)
      (available lime)
      (is-empty juicer)
      (is-halved lime)
      (on lime cutting_board)
    )
    :effect (and
      (available lime_juice)
      (contains juicer lime_juice)
      (in lime_juice juicer)
      (is-squeezed lime)
      (not (is-empty juicer))
      (not (is-halved lime))
      (not (on lime cutting_board))
    )
  )

  (:action pour_u70
    ; unit 70: pour from 07-guacamole.foon:90
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {avocado}), avocado (in [bowl], mashed) -> bowl (contains {avocado, lime juice}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (available avocado)
      (available bowl)
      (available juicer)
      (available lime_juice)
      (contains bowl avocado)
      (contains juicer lime_juice)
      (in avocado bowl)
      (in lime_juice juicer)
      (is-mashed avocado)
    )
    :effect (and
      (contains bowl lime_juice)
      (in lime_juice bowl)
      (not (in lime_juice juicer))
    )
  )

  (:action pick-and-place_u71
    ; unit 71: pick-and-place from 07-guacamole.foon:144
    ; pick-and-place: bowl (contains {avocado, lime juice}), onion (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion}), onion (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available onion)
      (contains bowl avocado)
      (contains bowl lime_juice)
      (is-chopped onion)
      (on onion cutting_board)
    )
    :effect (and
      (contains bowl onion)
      (in onion bowl)
      (not (on onion cutting_board))
    )
  )

  (:action pick-and-place_u72
    ; unit 72: pick-and-place from 07-guacamole.foon:181
    ; pick-and-place: bowl (contains {avocado, lime juice, onion}), tomato (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion, tomato}), tomato (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available tomato)
      (contains bowl avocado)
      (contains bowl lime_juice)
      (contains bowl onion)
      (is-chopped tomato)
      (on tomato cutting_board)
    )
    :effect (and
      (contains bowl tomato)
      (in tomato bowl)
      (not (on tomato cutting_board))
    )
  )

  (:action pick-and-place_u73
    ; unit 73: pick-and-place from 07-guacamole.foon:193
    ; pick-and-place: cutting board (empty), cilantro (fresh) -> cutting board (contains {cilantro}), cilantro (fresh, on [cutting board])
    :parameters ()
    :precondition (and
      (available cilantro)
      (available cutting_board)
      (is-empty cutting_board)
      (is-fresh cilantro)
    )
    :effect (and
      (contains cutting_board cilantro)
      (on cilantro cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action chop_u74
    ; unit 74: chop from 07-guacamole.foon:204
    ; chop: cutting board (contains {cilantro}), cilantro (fresh, on [cutting board]), knife -> cutting board (contains {cilantro}), cilantro (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (available cilantro)
      (available cutting_board)
      (available knife)
      (contains cutting_board cilantro)
      (is-fresh cilantro)
      (on cilantro cutting_board)
    )
    :effect (and
      (is-chopped cilantro)
      (not (is-fresh cilantro))
    )
  )

  (:action pick-and-place_u75
    ; unit 75: pick-and-place from 07-guacamole.foon:218
    ; pick-and-place: bowl (contains {avocado, lime juice, onion, tomato}), cilantro (chopped, on [cutting board]) -> bowl (contains {avocado, cilantro, lime juice, onion, tomato}), cilantro (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available cilantro)
      (contains bowl avocado)
      (contains bowl lime_juice)
      (contains bowl onion)
      (contains bowl tomato)
      (is-chopped cilantro)
      (on cilantro cutting_board)
    )
    :effect (and
      (contains bowl cilantro)
      (in cilantro bowl)
      (not (on cilantro cutting_board))
    )
  )

  (:action sprinkle_u76
    ; unit 76: sprinkle from 07-guacamole.foon:230
    ; sprinkle: bowl (contains {avocado, cilantro, lime juice, onion, tomato}), salt (granulated) -> bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato}), salt (in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available salt)
      (contains bowl avocado)
      (contains bowl cilantro)
      (contains bowl lime_juice)
      (contains bowl onion)
      (contains bowl tomato)
      (is-granulated salt)
    )
    :effect (and
      (contains bowl salt)
      (in salt bowl)
      (not (is-granulated salt))
    )
  )

  (:action pick-and-place_u78
    ; unit 78: pick-and-place from 08-greek_salad.foon:3
    ; pick-and-place: cutting board (empty), cucumber (whole) -> cutting board (contains {cucumber}), cucumber (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available cucumber)
      (available cutting_board)
      (is-empty cutting_board)
      (is-whole cucumber)
    )
    :effect (and
      (contains cutting_board cucumber)
      (on cucumber cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action slice_u79
    ; unit 79: slice from 08-greek_salad.foon:14
    ; slice: cutting board (contains {cucumber}), cucumber (on [cutting board], whole), knife -> cutting board (contains {cucumber}), cucumber (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (available cucumber)
      (available cutting_board)
      (available knife)
      (contains cutting_board cucumber)
      (is-whole cucumber)
      (on cucumber cutting_board)
    )
    :effect (and
      (is-sliced cucumber)
      (not (is-whole cucumber))
    )
  )

  (:action slice_u80
    ; unit 80: slice from 08-greek_salad.foon:78
    ; slice: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available onion)
      (contains cutting_board onion)
      (is-peeled onion)
      (on onion cutting_board)
    )
    :effect (and
      (is-sliced onion)
      (not (is-peeled onion))
    )
  )

  (:action pick-and-place_u81
    ; unit 81: pick-and-place from 08-greek_salad.foon:92
    ; pick-and-place: bowl (empty), cucumber (on [cutting board], sliced) -> bowl (contains {cucumber}), cucumber (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (available bowl)
      (available cucumber)
      (is-empty bowl)
      (is-sliced cucumber)
      (on cucumber cutting_board)
    )
    :effect (and
      (contains bowl cucumber)
      (in cucumber bowl)
      (not (is-empty bowl))
      (not (on cucumber cutting_board))
    )
  )

  (:action pick-and-place_u82
    ; unit 82: pick-and-place from 08-greek_salad.foon:104
    ; pick-and-place: bowl (contains {cucumber}), tomato (chopped, on [cutting board]) -> bowl (contains {cucumber, tomato}), tomato (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available tomato)
      (contains bowl cucumber)
      (is-chopped tomato)
      (on tomato cutting_board)
    )
    :effect (and
      (contains bowl tomato)
      (in tomato bowl)
      (not (on tomato cutting_board))
    )
  )

  (:action pick-and-place_u83
    ; unit 83: pick-and-place from 08-greek_salad.foon:116
    ; pick-and-place: bowl (contains {cucumber, tomato}), onion (on [cutting board], sliced) -> bowl (contains {cucumber, onion, tomato}), onion (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (available bowl)
      (available onion)
      (contains bowl cucumber)
      (contains bowl tomato)
      (is-sliced onion)
      (on onion cutting_board)
    )
    :effect (and
      (contains bowl onion)
      (in onion bowl)
      (not (on onion cutting_board))
    )
  )

  (:action pick-and-place_u89
    ; unit 89: pick-and-place from 09-fruit_salad.foon:3
    ; pick-and-place: cutting board (empty), strawberry (whole) -> cutting board (contains {strawberry}), strawberry (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available strawberry)
      (is-empty cutting_board)
      (is-whole strawberry)
    )
    :effect (and
      (contains cutting_board strawberry)
      (on strawberry cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action slice_u90
    ; unit 90: slice from 09-fruit_salad.foon:14
    ; slice: cutting board (contains {strawberry}), strawberry (on [cutting board], whole), knife -> cutting board (contains {strawberry}), strawberry (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available strawberry)
      (contains cutting_board strawberry)
      (is-whole strawberry)
      (on strawberry cutting_board)
    )
    :effect (and
      (is-sliced strawberry)
      (not (is-whole strawberry))
    )
  )

  (:action peel_u91
    ; unit 91: peel from 09-fruit_salad.foon:28
    ; peel: banana (whole) -> banana (peeled)
    :parameters ()
    :precondition (and
      (available banana)
      (is-whole banana)
    )
    :effect (and
      (is-peeled banana)
      (not (is-whole banana))
    )
  )

  (:action pick-and-place_u92
    ; unit 92: pick-and-place from 09-fruit_salad.foon:34
    ; pick-and-place: cutting board (empty), banana (peeled) -> cutting board (contains {banana}), banana (on [cutting board], peeled)
    :parameters ()
    :precondition (and
      (available banana)
      (available cutting_board)
      (is-empty cutting_board)
      (is-peeled banana)
    )
    :effect (and
      (contains cutting_board banana)
      (on banana cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action slice_u93
    ; unit 93: slice from 09-fruit_salad.foon:45
    ; slice: cutting board (contains {banana}), banana (on [cutting board], peeled), knife -> cutting board (contains {banana}), banana (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (available banana)
      (available cutting_board)
      (available knife)
      (contains cutting_board banana)
      (is-peeled banana)
      (on banana cutting_board)
    )
    :effect (and
      (is-sliced banana)
      (not (is-peeled banana))
    )
  )

  (:action pick-and-place_u94
    ; unit 94: pick-and-place from 09-fruit_salad.foon:59
    ; pick-and-place: bowl (empty), strawberry (on [cutting board], sliced) -> bowl (contains {strawberry}), strawberry (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (available bowl)
      (available strawberry)
      (is-empty bowl)
      (is-sliced strawberry)
      (on strawberry cutting_board)
    )
    :effect (and
      (contains bowl strawberry)
      (in strawberry bowl)
      (not (is-empty bowl))
      (not (on strawberry cutting_board))
    )
  )

  (:action pick-and-place_u95
    ; unit 95: pick-and-place from 09-fruit_salad.foon:71
    ; pick-and-place: bowl (contains {strawberry}), banana (on [cutting board], sliced) -> bowl (contains {banana, strawberry}), banana (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (available banana)
      (available bowl)
      (contains bowl strawberry)
      (is-sliced banana)
      (on banana cutting_board)
    )
    :effect (and
      (contains bowl banana)
      (in banana bowl)
      (not (on banana cutting_board))
    )
  )

  (:action pour_u96
    ; unit 96: pour from 09-fruit_salad.foon:121
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {banana, strawberry}) -> bowl (contains {banana, lime juice, strawberry}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available juicer)
      (available lime_juice)
      (contains bowl banana)
      (contains bowl strawberry)
      (contains juicer lime_juice)
      (in lime_juice juicer)
    )
    :effect (and
      (contains bowl lime_juice)
      (in lime_juice bowl)
      (not (in lime_juice juicer))
    )
  )
)
